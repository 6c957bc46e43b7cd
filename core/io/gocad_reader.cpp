#include "io/gocad_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/gocad_line_tokenizer.h"
#include "io/gocad_model3d_header.h"
#include "io/gocad_model_builder.h"
#include "io/gocad_tsurf_parser.h"

#include <fstream>
#include <optional>
#include <vector>

namespace stratamesh {

Model readGocad(std::istream &in, const std::string &fileName)
{
    GocadLineTokenizer tok(in, fileName);
    std::optional<GocadModel3dHeader> header;
    std::vector<GocadTSurf> tsurfs;
    bool first = true;
    while (tok.next()) {
        GocadObjectInfo info;
        if (!readGocadObjectLine(tok, info))
            tok.fail(first ? QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "not a Gocad file: expected 'GOCAD <type>'")
                           : QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "expected 'GOCAD <type>' to start the next object"));
        if (gocadKeywordEquals(info.type, "Model3d")) {
            if (!first)
                tok.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "a Model3d object must come first in the file"));
            header = parseGocadModel3dHeader(tok, info);
        } else if (gocadKeywordEquals(info.type, "TSurf")) {
            tsurfs.push_back(parseGocadTSurf(tok, info));
        } else {
            skipGocadObject(tok, info);
        }
        first = false;
    }
    if (first)
        throw FileError(fileName, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "empty file: no GOCAD object"));
    if (header)
        return buildGocadModel3d(*header, std::move(tsurfs), fileName);
    return buildGocadSurfaces(std::move(tsurfs), fileName);
}

Model readGocadFile(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "cannot open the file (missing or not readable)"));
    Model model = readGocad(in, path);
    if (in.bad())
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "read error"));
    return model;
}

} // namespace stratamesh
