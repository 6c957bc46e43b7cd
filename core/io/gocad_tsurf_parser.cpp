#include "io/gocad_tsurf_parser.h"
#include "common/translate_noop.h"

#include <unordered_map>
#include <utility>

namespace stratamesh {

namespace {

class TSurfParser {
public:
    TSurfParser(GocadLineTokenizer &tok, const GocadObjectInfo &info) : m_tok(tok)
    {
        m_result.info = info;
    }

    GocadTSurf run()
    {
        while (m_tok.next()) {
            if (m_tok.is(0, "END")) {
                m_result.endLine = m_tok.lineNumber();
                finish();
                return std::move(m_result);
            }
            if (m_tok.is(0, "GOCAD"))
                failMissingGocadEnd(m_tok, m_result.info, false);
            readRecord();
        }
        failMissingGocadEnd(m_tok, m_result.info, true);
    }

private:
    struct VertexRef {
        int face = -1;
        int local = -1;
        int line = 0;
    };

    void readRecord()
    {
        const GocadLineTokenizer &t = m_tok;
        if (t.is(0, "VRTX") || t.is(0, "PVRTX"))
            readVertex();
        else if (t.is(0, "ATOM") || t.is(0, "PATOM"))
            readAtom();
        else if (t.is(0, "TRGL"))
            readTriangle();
        else if (t.is(0, "TFACE") || t.is(0, "3DFace"))
            startFace();
        else if (t.is(0, "BSTONE")) {
            t.requireTokens(2, "BSTONE vertex_id");
            m_stones.push_back(
                {t.integer(1, QT_TRANSLATE_NOOP("stratamesh::Core", "BSTONE vertex id")),
                 t.lineNumber()});
        } else if (t.is(0, "BORDER")) {
            t.requireTokens(4, "BORDER id corner_vertex_id next_vertex_id");
            m_result.borders.push_back(
                {t.integer(1, QT_TRANSLATE_NOOP("stratamesh::Core", "BORDER id")),
                 t.integer(2, QT_TRANSLATE_NOOP("stratamesh::Core", "BORDER corner vertex id")),
                 t.integer(3, QT_TRANSLATE_NOOP("stratamesh::Core", "BORDER next vertex id")),
                 t.lineNumber()});
        } else if (t.is(0, "GEOLOGICAL_FEATURE")) {
            m_result.geologicalFeature = t.joined(1);
        } else if (t.is(0, "GEOLOGICAL_TYPE")) {
            m_result.geologicalType = t.joined(1);
        } else {
            // Anything else is metadata (properties, display, stratigraphy): skipped.
            readGocadCommonLine(m_tok, m_result.info);
        }
    }

    void startFace()
    {
        m_result.faces.emplace_back();
        m_result.faces.back().line = m_tok.lineNumber();
        m_imported.clear();
    }

    // Some writers omit TFACE for a single patch: the first record opens it.
    int currentFace()
    {
        if (m_result.faces.empty())
            startFace();
        return int(m_result.faces.size()) - 1;
    }

    void defineVertex(long long id, const Vec3 &p)
    {
        const int face = currentFace();
        GocadFace &f = m_result.faces[face];
        const auto [it, inserted] =
            m_ids.try_emplace(id, VertexRef{face, int(f.vertices.size()), m_tok.lineNumber()});
        if (!inserted)
            m_tok.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "vertex id %1 is already defined at line %2"),
                {std::to_string(id), std::to_string(it->second.line)}});
        f.vertices.push_back(p);
    }

    void readVertex()
    {
        m_tok.requireTokens(5, "VRTX id x y z");
        const long long id = m_tok.integer(1, QT_TRANSLATE_NOOP("stratamesh::Core", "vertex id"));
        const Vec3 p(m_tok.coordinate(2, QT_TRANSLATE_NOOP("stratamesh::Core", "x coordinate")),
                     m_tok.coordinate(3, QT_TRANSLATE_NOOP("stratamesh::Core", "y coordinate")),
                     m_tok.coordinate(4, QT_TRANSLATE_NOOP("stratamesh::Core", "z coordinate")));
        defineVertex(id, p);
    }

    // ATOM id ref: a new vertex at the position of `ref`. Whether `ref` lies in this TFACE (a cut)
    // or in an earlier one (a border shared by two patches), the new vertex is local to this face.
    void readAtom()
    {
        m_tok.requireTokens(3, "ATOM id referenced_vertex_id");
        const long long id = m_tok.integer(1, QT_TRANSLATE_NOOP("stratamesh::Core", "vertex id"));
        const long long ref =
            m_tok.integer(2, QT_TRANSLATE_NOOP("stratamesh::Core", "referenced vertex id"));
        const auto it = m_ids.find(ref);
        if (it == m_ids.end())
            m_tok.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "ATOM %1 refers to vertex %2, which is not defined before it"),
                {std::to_string(id), std::to_string(ref)}});
        const Vec3 p = m_result.faces[it->second.face].vertices[it->second.local];
        defineVertex(id, p);
    }

    int localVertex(long long id, int face)
    {
        const auto it = m_ids.find(id);
        if (it == m_ids.end())
            m_tok.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "TRGL refers to vertex %1, which is not defined in %2"),
                {std::to_string(id), describeGocadObject(m_result.info)}});
        if (it->second.face == face)
            return it->second.local;
        // A vertex of an earlier TFACE used directly: treated like an ATOM of it, once per face.
        GocadFace &f = m_result.faces[face];
        const auto [imp, inserted] = m_imported.try_emplace(id, int(f.vertices.size()));
        if (inserted)
            f.vertices.push_back(m_result.faces[it->second.face].vertices[it->second.local]);
        return imp->second;
    }

    void readTriangle()
    {
        m_tok.requireTokens(4, "TRGL vertex_id vertex_id vertex_id");
        const int face = currentFace();
        const long long a =
            m_tok.integer(1, QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL vertex id"));
        const long long b =
            m_tok.integer(2, QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL vertex id"));
        const long long c =
            m_tok.integer(3, QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL vertex id"));
        if (a == b || b == c || a == c)
            m_tok.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL uses the same vertex id twice"));
        const Triangle tri{localVertex(a, face), localVertex(b, face), localVertex(c, face)};
        m_result.faces[face].triangles.push_back(tri);
    }

    void requireVertex(long long id, int line, const char *what)
    {
        if (m_ids.find(id) == m_ids.end())
            m_tok.failAt(
                line,
                MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "%1 refers to vertex %2, which is not defined in %3"),
                    {std::string(what), std::to_string(id), describeGocadObject(m_result.info)}});
    }

    void finish()
    {
        const std::string what = describeGocadObject(m_result.info);
        if (m_result.faces.empty())
            m_tok.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "%1 has no TFACE and no triangle"), {what}});
        for (const GocadFace &f : m_result.faces)
            if (f.triangles.empty())
                m_tok.failAt(f.line, MessageText{QT_TRANSLATE_NOOP(
                                                     "stratamesh::Core",
                                                     "TFACE of %1 has no triangle (empty surface)"),
                                                 {what}});
        for (const auto &[id, line] : m_stones) {
            requireVertex(id, line, "BSTONE");
            m_result.borderStones.push_back(id);
        }
        for (const GocadBorder &b : m_result.borders) {
            requireVertex(b.corner, b.line, "BORDER");
            requireVertex(b.next, b.line, "BORDER");
        }
        for (GocadFace &f : m_result.faces)
            compact(f);
    }

    // Keeps only the vertices the triangles use (file order kept) and converts to z-up.
    void compact(GocadFace &f) const
    {
        std::vector<int> newIndex(f.vertices.size(), -1);
        for (const Triangle &t : f.triangles)
            for (int v : t)
                newIndex[v] = 0;
        std::vector<Vec3> kept;
        kept.reserve(f.vertices.size());
        for (std::size_t v = 0; v < f.vertices.size(); ++v) {
            if (newIndex[v] < 0)
                continue;
            newIndex[v] = int(kept.size());
            Vec3 p = f.vertices[v];
            if (m_result.info.zPositiveDepth)
                p.z() = -p.z();
            // Adding +0.0 turns -0.0 into +0.0, so equal points also have equal bits for hashing.
            kept.emplace_back(p.x() + 0.0, p.y() + 0.0, p.z() + 0.0);
        }
        for (Triangle &t : f.triangles)
            for (int &v : t)
                v = newIndex[v];
        f.vertices = std::move(kept);
    }

    GocadLineTokenizer &m_tok;
    GocadTSurf m_result;
    std::unordered_map<long long, VertexRef> m_ids;
    std::unordered_map<long long, int> m_imported; // earlier-face ids copied into the current face
    std::vector<std::pair<long long, int>> m_stones;
};

} // namespace

GocadTSurf parseGocadTSurf(GocadLineTokenizer &tok, const GocadObjectInfo &info)
{
    return TSurfParser(tok, info).run();
}

} // namespace stratamesh
