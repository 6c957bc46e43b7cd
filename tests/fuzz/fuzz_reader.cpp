// One reader under libFuzzer: each input is written as a file with the extension this harness
// was built for (STRATAMESH_FUZZ_EXTENSION) and read as a model, or as a mesh for STL and PLY.
// A FileError (or InputError) is the expected answer to a bad file; any other exception, a crash,
// a sanitizer report, an allocation over 1 GB or a run over 10 s is a finding.
#include "common/error.h"
#include "io/mesh_reader.h"
#include "io/model_reader.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace {

std::string inputPath()
{
    const char *dir = std::getenv("TMPDIR");
    std::string path = std::string(dir && *dir ? dir : "/tmp") + "/stratamesh-fuzz-"
                       + std::to_string(getpid()) + STRATAMESH_FUZZ_EXTENSION;
    return path;
}

// Removed at exit: each fuzz run had left its inputs in /tmp (88 after four CI runs).
struct InputFile {
    std::string path = inputPath();
    ~InputFile() { std::remove(path.c_str()); }
};

const std::string &path()
{
    static const InputFile file;
    return file.path;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    std::FILE *f = std::fopen(path().c_str(), "wb");
    if (!f)
        std::abort();
    if (size > 0 && std::fwrite(data, 1, size, f) != size)
        std::abort();
    std::fclose(f);
    const std::string ext = STRATAMESH_FUZZ_EXTENSION;
    try {
        if (ext == ".stl" || ext == ".ply")
            stratamesh::readVolumeMesh(path());
        else
            stratamesh::readModel(path());
    } catch (const stratamesh::FileError &) {
    } catch (const stratamesh::InputError &) {
    }
    return 0;
}
