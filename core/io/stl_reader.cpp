#include "io/stl_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/formats.h"
#include "io/text_cursor.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <unordered_map>

namespace stratamesh {

namespace {

struct PointHash {
    std::size_t operator()(const std::array<double, 3> &p) const
    {
        std::size_t h = 0;
        for (double v : p)
            h = h * 1000003u ^ std::hash<double>()(v);
        return h;
    }
};

// Corners with equal coordinates (bit for bit once -0 is +0) become one vertex.
class Welder {
public:
    explicit Welder(VolumeMesh &mesh) : m_mesh(mesh) {}
    int vertex(const Vec3 &p)
    {
        const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
        const auto [it, inserted] =
            m_index.try_emplace(key, static_cast<int>(m_mesh.points.size()));
        if (inserted)
            m_mesh.points.emplace_back(key[0], key[1], key[2]);
        return it->second;
    }

private:
    VolumeMesh &m_mesh;
    std::unordered_map<std::array<double, 3>, int, PointHash> m_index;
};

VolumeMesh oneSurface(const std::string &path)
{
    VolumeMesh m;
    m.name = fileStem(path);
    m.surfaces.push_back({m.name, m.name, FeatureType::Unknown});
    return m;
}

// A facet whose corners weld into fewer than three vertices has no area and no orientation.
bool degenerate(const Triangle &t)
{
    return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
}

VolumeMesh readAsciiStl(const std::string &path)
{
    TextCursor c(path);
    VolumeMesh m = oneSurface(path);
    Welder welder(m);
    c.nextNonBlank("solid");
    if (c.tokens().front() != "solid")
        c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "an ASCII STL file starts with \"solid\""));
    bool inSolid = true;
    long long facet = 0;
    auto expect = [&](const char *word, std::size_t tokens) {
        c.nextNonBlank(word);
        const auto t = c.tokens();
        if (t.front() != word || t.size() < tokens)
            c.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"%1\", found \"%2\""),
                            {word, std::string(c.line())}});
        return t;
    };
    while (c.next()) {
        const auto t = c.tokens();
        if (t.empty())
            continue;
        if (!inSolid) {
            if (t.front() != "solid")
                c.fail(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core", "text after endsolid: \"%1\""),
                    {std::string(c.line())}});
            inSolid = true;
            continue;
        }
        if (t.front() == "endsolid") {
            inSolid = false;
            continue;
        }
        if (t.front() != "facet")
            c.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "expected \"facet\" or \"endsolid\", found \"%1\""),
                            {std::string(c.line())}});
        ++facet;
        expect("outer", 2);
        Triangle tri{};
        for (int k = 0; k < 3; ++k) {
            const auto v = expect("vertex", 4);
            const Vec3 p(c.toDouble(v[1], "a coordinate"), c.toDouble(v[2], "a coordinate"),
                         c.toDouble(v[3], "a coordinate"));
            if (MessageText problem = pointProblem(p); !problem.pattern.empty())
                c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "facet %1: %2"),
                                   {std::to_string(facet)},
                                   {std::move(problem)}});
            tri[k] = welder.vertex(p);
        }
        c.nextNonBlank("endloop");
        if (c.tokens().front() == "vertex")
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "facet %1 has more than three vertices"),
                {std::to_string(facet)}});
        if (c.tokens().front() != "endloop")
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"endloop\", found \"%1\""),
                {std::string(c.line())}});
        expect("endfacet", 1);
        if (degenerate(tri))
            c.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "facet %1 has two equal corners (degenerate facet)"),
                            {std::to_string(facet)}});
        m.triangles.push_back(tri);
        m.triangleSurface.push_back(0);
    }
    if (inSolid)
        throw FileError(
            path, c.lineNumber() + 1,
            QT_TRANSLATE_NOOP("stratamesh::Core", "file ends before endsolid (truncated file?)"));
    return m;
}

float floatAt(const char *bytes)
{
    float v;
    std::memcpy(&v, bytes, sizeof v);
    return v;
}

VolumeMesh readBinaryStl(const std::string &path, const std::string &data)
{
    std::uint32_t count = 0;
    std::memcpy(&count, data.data() + 80, sizeof count);
    const std::size_t expected = 84 + 50 * std::size_t(count);
    if (data.size() != expected)
        throw FileError(
            path, 0,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "binary STL of %1 bytes, its header announces %2 facets (%3 "
                                  "bytes): truncated or not an STL file"),
                {std::to_string(data.size()), std::to_string(count), std::to_string(expected)}});
    VolumeMesh m = oneSurface(path);
    Welder welder(m);
    m.triangles.reserve(count);
    for (std::uint32_t f = 0; f < count; ++f) {
        const char *corners = data.data() + 84 + 50 * std::size_t(f) + 12; // after the normal
        Triangle tri{};
        for (int k = 0; k < 3; ++k) {
            const char *xyz = corners + 12 * k;
            const Vec3 p(floatAt(xyz), floatAt(xyz + 4), floatAt(xyz + 8));
            if (MessageText problem = pointProblem(p); !problem.pattern.empty())
                throw FileError(path, 0,
                                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "facet %1: %2"),
                                            {std::to_string(f + 1)},
                                            {std::move(problem)}});
            tri[k] = welder.vertex(p);
        }
        if (degenerate(tri))
            throw FileError(
                path, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "facet %1 has two equal corners (degenerate facet)"),
                            {std::to_string(f + 1)}});
        m.triangles.push_back(tri);
        m.triangleSurface.push_back(0);
    }
    return m;
}

} // namespace

VolumeMesh readStl(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open the file"));
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t first = data.find_first_not_of(" \t\r\n");
    const bool solid = first != std::string::npos && data.compare(first, 5, "solid") == 0;
    // Binary files may also begin with "solid" in their free header: their size decides.
    if (data.size() >= 84) {
        std::uint32_t count = 0;
        std::memcpy(&count, data.data() + 80, sizeof count);
        if (data.size() == 84 + 50 * std::size_t(count) || !solid)
            return readBinaryStl(path, data);
    }
    if (!solid)
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "neither an ASCII STL (starting with \"solid\") "
                                          "nor a binary STL (84 bytes or more)"));
    return readAsciiStl(path);
}

} // namespace stratamesh
