#include "io/gocad_model3d_header.h"
#include "common/translate_noop.h"

namespace stratamesh {

namespace {

// Ids after a REGION/SURFACE/LAYER line, possibly over several lines, ended by 0.
std::vector<GocadListedId> readZeroTerminatedList(GocadLineTokenizer &tok, const std::string &what)
{
    const int start = tok.lineNumber();
    const std::string where = what + " (line " + std::to_string(start) + ")";
    std::vector<GocadListedId> ids;
    while (tok.next()) {
        for (std::size_t i = 0; i < tok.size(); ++i) {
            long long v = 0;
            if (!parseGocadInteger(tok.token(i), v)) {
                if (i == 0)
                    tok.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                           "list of ids of %1 is not ended by 0"),
                                         {where}});
                tok.fail(
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "'%1' in the list of %2 is not an integer id"),
                                {std::string(tok.token(i)), where}});
            }
            if (v == 0)
                return ids;
            ids.push_back({v, tok.lineNumber()});
        }
    }
    tok.failAt(
        tok.lastLineNumber(),
        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "file ends inside the list of ids of %1 (truncated file?)"),
                    {where}});
}

void readKeyTriangle(GocadLineTokenizer &tok, GocadHeaderFace &face)
{
    // The key triangle is optional for us: a following line that does not start with a number
    // belongs to the next record.
    if (!tok.next())
        return;
    double unused = 0.0;
    if (!parseGocadNumber(tok.token(0), unused)) {
        tok.pushBack();
        return;
    }
    for (int k = 0; k < 3; ++k) {
        if (k > 0 && !tok.next())
            tok.failAt(
                tok.lastLineNumber(),
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "file ends inside the key triangle of TFACE %1 (truncated file?)"),
                            {std::to_string(face.id)}});
        tok.requireTokens(3, "x y z of a key triangle point of TFACE " + std::to_string(face.id));
        face.key[k] =
            Vec3(tok.coordinate(0, QT_TRANSLATE_NOOP("stratamesh::Core", "x coordinate")),
                 tok.coordinate(1, QT_TRANSLATE_NOOP("stratamesh::Core", "y coordinate")),
                 tok.coordinate(2, QT_TRANSLATE_NOOP("stratamesh::Core", "z coordinate")));
    }
    face.hasKey = true;
}

GocadHeaderFace readFace(GocadLineTokenizer &tok)
{
    tok.requireTokens(4, "TFACE id geological_type tsurf_name");
    GocadHeaderFace face;
    face.id = tok.integer(1, QT_TRANSLATE_NOOP("stratamesh::Core", "TFACE id"));
    face.type = std::string(tok.token(2));
    face.tsurf = tok.joined(3);
    face.line = tok.lineNumber();
    readKeyTriangle(tok, face);
    return face;
}

GocadIdList readNamedList(GocadLineTokenizer &tok, bool hasId)
{
    GocadIdList list;
    list.line = tok.lineNumber();
    const std::string keyword(tok.token(0));
    if (hasId) {
        tok.requireTokens(2, keyword + " id name");
        list.id = tok.integer(1, keyword + " id");
        list.name = tok.joined(2);
    } else {
        list.name = tok.joined(1);
    }
    list.ids = readZeroTerminatedList(tok, keyword + " '" + list.name + "'");
    return list;
}

} // namespace

GocadModel3dHeader parseGocadModel3dHeader(GocadLineTokenizer &tok, const GocadObjectInfo &info)
{
    GocadModel3dHeader h;
    h.info = info;
    while (tok.next()) {
        if (tok.is(0, "END")) {
            h.endLine = tok.lineNumber();
            if (h.info.zPositiveDepth)
                for (GocadHeaderFace &f : h.faces)
                    for (Vec3 &p : f.key)
                        p.z() = -p.z() + 0.0;
            return h;
        }
        if (tok.is(0, "GOCAD"))
            failMissingGocadEnd(tok, h.info, false);
        if (tok.is(0, "TSURF")) {
            tok.requireTokens(2, "TSURF name");
            h.tsurfs.push_back({tok.joined(1), tok.lineNumber()});
        } else if (tok.is(0, "TFACE")) {
            h.faces.push_back(readFace(tok));
        } else if (tok.is(0, "REGION")) {
            h.regions.push_back(readNamedList(tok, true));
        } else if (tok.is(0, "SURFACE")) {
            h.surfaceGroups.push_back(readNamedList(tok, false));
        } else if (tok.is(0, "LAYER")) {
            h.layers.push_back(readNamedList(tok, false));
        } else if (tok.is(0, "FAULT_BLOCK")) {
            readNamedList(tok, false); // fault blocks are not used: only consumed
        } else {
            readGocadCommonLine(tok, h.info);
        }
    }
    failMissingGocadEnd(tok, h.info, true);
}

} // namespace stratamesh
