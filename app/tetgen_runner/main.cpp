// stratamesh-tetgen: runs TetGen 1.5 (Si 2015, ACM TOMS 41(2)) on one PLC in a process of its
// own. TetGen ends its host on bad input (uncaught `throw int`, assertions, segfaults while
// unwinding, runs that never end; formats.md §4.5), so core/volume/tetgen_runner.h starts this
// helper as a child process and maps how it ended to a typed outcome. It links libtet only.
//
//   stratamesh-tetgen SWITCHES INPUT.poly OUTPUT.tets
//
// INPUT is a TetGen .poly file (core/volume/tetgen_poly_writer.h). OUTPUT is written to a
// temporary name and renamed, so it exists only when complete (format in
// core/volume/tetgen_result_file.h). Exit status: 0 done; 2 usage; 3 unreadable input; 4 unwritable
// output; 9 out of memory; 10 + TetGen's error code (11 out of memory, 12 internal error, 13
// self-intersection, 14 small feature size, 15 close facets, 20 input error). TetGen's own messages
// go to stdout.
#ifndef TETLIBRARY
#define TETLIBRARY // the library throws instead of exiting
#endif
#include <tetgen.h>

#include "volume/tetgen_result_file.h"

#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace {

const char *tetgenErrorMeaning(int code)
{
    switch (code) {
    case 1:
        return "out of memory";
    case 2:
        return "internal error";
    case 3:
        return "self-intersection in the input";
    case 4:
        return "very small input feature size";
    case 5:
        return "two very close input facets";
    case 10:
        return "input error";
    default:
        return "unknown error";
    }
}

bool writeResult(const tetgenio &out, const std::string &path)
{
    using namespace stratamesh::tetgen_result;
    const std::string temporary = path + ".part";
    std::FILE *f = std::fopen(temporary.c_str(), "wb");
    if (!f)
        return false;
    const int base = out.firstnumber;
    Header header;
    header.points = out.numberofpoints;
    header.tets = out.numberoftetrahedra;
    header.faces = out.numberoftrifaces;
    const auto pointValues = static_cast<std::size_t>(3 * header.points);
    bool ok = std::fwrite(&header, sizeof header, 1, f) == 1;
    ok = ok && std::fwrite(out.pointlist, sizeof(double), pointValues, f) == pointValues;
    std::vector<std::int32_t> tets(5 * header.tets);
    for (std::int64_t t = 0; t < header.tets; ++t) {
        for (int k = 0; k < 4; ++k)
            tets[5 * t + k] = out.tetrahedronlist[t * out.numberofcorners + k] - base;
        tets[5 * t + 4] = out.numberoftetrahedronattributes > 0 ? static_cast<std::int32_t>(
                              out.tetrahedronattributelist[t * out.numberoftetrahedronattributes])
                                                                : 0;
    }
    ok = ok && std::fwrite(tets.data(), sizeof(std::int32_t), tets.size(), f) == tets.size();
    std::vector<std::int32_t> faces(4 * header.faces);
    for (std::int64_t i = 0; i < header.faces; ++i) {
        for (int k = 0; k < 3; ++k)
            faces[4 * i + k] = out.trifacelist[3 * i + k] - base;
        faces[4 * i + 3] = out.trifacemarkerlist ? out.trifacemarkerlist[i] : 0;
    }
    ok = ok && std::fwrite(faces.data(), sizeof(std::int32_t), faces.size(), f) == faces.size();
    ok = std::fclose(f) == 0 && ok;
    return ok && std::rename(temporary.c_str(), path.c_str()) == 0;
}

} // namespace

int main(int argc, char **argv)
{
    // Line buffered so that TetGen's last message before a crash reaches the runner's log.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    if (argc != 4) {
        std::fprintf(stderr, "usage: stratamesh-tetgen SWITCHES INPUT.poly OUTPUT.tets\n");
        return 2;
    }
    std::string input = argv[2];
    if (input.size() < 5 || input.compare(input.size() - 5, 5, ".poly") != 0) {
        std::fprintf(stderr, "[stratamesh-tetgen] %s is not a .poly file\n", argv[2]);
        return 2;
    }
    try {
        tetgenio in, out;
        std::vector<char> base(input.begin(), input.end() - 5);
        base.push_back('\0');
        if (!in.load_poly(base.data())) {
            std::fprintf(stderr, "[stratamesh-tetgen] cannot read %s\n", argv[2]);
            return 3;
        }
        std::vector<char> switches(argv[1], argv[1] + std::strlen(argv[1]) + 1);
        tetrahedralize(switches.data(), &in, &out);
        if (!writeResult(out, argv[3])) {
            std::fprintf(stderr, "[stratamesh-tetgen] cannot write %s\n", argv[3]);
            return 4;
        }
    } catch (int code) {
        std::fflush(stdout);
        std::fprintf(stderr, "[stratamesh-tetgen] TetGen error %d (%s)\n", code,
                     tetgenErrorMeaning(code));
        return 10 + code;
    } catch (const std::bad_alloc &) {
        std::fflush(stdout);
        std::fprintf(stderr, "[stratamesh-tetgen] out of memory\n");
        return 9;
    }
    return 0;
}
