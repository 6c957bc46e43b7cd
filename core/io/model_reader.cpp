#include "io/model_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/formats.h"

#include <algorithm>
#include <filesystem>

namespace stratamesh {

bool isReadableModelFile(const std::string &path)
{
    return isFileFor(path, FormatUse::ReadModel);
}

Model readModel(const std::string &path)
{
    const FileFormat *format = findFormat(path);
    if (format == nullptr || !format->readsModel())
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "unknown model file extension '%1' (expected %2)"),
                        {fileExtension(path), extensionList(FormatUse::ReadModel)}});
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "cannot open the file (missing or not a regular file)"));
    // Volume meshes give their surfaces and regions, cells dropped (modelFromMesh).
    const Model model = format->readModel(path);
    // An empty model would open as a "valid" one with nothing in it.
    const bool empty = std::all_of(model.surfaces.begin(), model.surfaces.end(),
                                   [](const Surface &s) { return s.triangles.empty(); });
    if (empty)
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "the file holds no surface triangle (an empty "
                                          "model; volume cells alone give no surface)"));
    return model;
}

} // namespace stratamesh
