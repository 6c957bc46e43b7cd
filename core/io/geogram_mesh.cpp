#include "io/geogram_mesh.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/coordinate_bound.h"

#include <algorithm>
#include <map>

namespace stratamesh {

namespace {

const std::string kVertices = "GEO::Mesh::vertices";
const std::string kEdges = "GEO::Mesh::edges";
const std::string kFacets = "GEO::Mesh::facets";
const std::string kFacetCorners = "GEO::Mesh::facet_corners";
const std::string kCells = "GEO::Mesh::cells";
const std::string kCellCorners = "GEO::Mesh::cell_corners";
const std::string kCellFacets = "GEO::Mesh::cell_facets";
constexpr std::uint32_t kNoId = 0xffffffffu;

[[noreturn]] void fail(const std::string &where, const std::string &cause)
{
    throw FileError(where, 0, cause);
}

[[noreturn]] void fail(const std::string &where, const MessageText &cause)
{
    throw FileError(where, 0, cause);
}

std::uint32_t itemCount(const GeogramFile &file, const std::string &set)
{
    const GeogramAttributeSet *s = file.findSet(set);
    return s ? s->items : 0;
}

const GeogramAttribute &required(const GeogramFile &file, const std::string &set,
                                 const std::string &name, std::uint32_t dimension,
                                 const std::string &where)
{
    const GeogramAttribute *a = file.find(set, name);
    if (!a)
        fail(where,
             MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "attribute '%1' of '%2' is missing"),
                         {name, set}});
    if (a->dimension != dimension)
        fail(where, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "attribute '%1' has dimension %2, expected %3"),
                                {name, std::to_string(a->dimension), std::to_string(dimension)}});
    return *a;
}

std::vector<std::uint32_t> vertexIds(const GeogramAttribute &a, std::size_t vertexCount,
                                     const std::string &where)
{
    std::vector<std::uint32_t> ids = geogramIndices(a, where);
    for (std::size_t i = 0; i < ids.size(); ++i)
        if (ids[i] >= vertexCount)
            fail(where, MessageText{QT_TRANSLATE_NOOP(
                                        "stratamesh::Core",
                                        "'%1' entry %2 is vertex %3, but the mesh has %4 vertices"),
                                    {a.name, std::to_string(i), std::to_string(ids[i]),
                                     std::to_string(vertexCount)}});
    return ids;
}

// Start corner of every item, plus the total: from an explicit *_ptr attribute, else `per` each.
std::vector<std::uint32_t> itemStarts(const GeogramFile &file, const std::string &set,
                                      const std::string &ptrName, std::uint32_t corners,
                                      std::uint32_t per, const std::string &where)
{
    const std::uint32_t n = itemCount(file, set);
    std::vector<std::uint32_t> starts;
    if (const GeogramAttribute *ptr = file.find(set, ptrName)) {
        starts = geogramIndices(*ptr, where);
        starts.push_back(corners);
        for (std::size_t i = 0; i + 1 < starts.size(); ++i)
            if (starts[i] > starts[i + 1] || starts[i + 1] > corners)
                fail(where,
                     MessageText{QT_TRANSLATE_NOOP(
                                     "stratamesh::Core",
                                     "'%1' of item %2 is out of order or beyond the %3 corners"),
                                 {ptrName, std::to_string(i), std::to_string(corners)}});
        if (!starts.empty() && starts.front() != 0)
            fail(where, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "'%1' does not start at corner 0"),
                                    {ptrName}});
        return starts;
    }
    if (std::uint64_t(n) * per != corners)
        fail(where,
             MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "%1 items of '%2' need %3 corners, the file has %4"),
                         {std::to_string(n), set, std::to_string(std::uint64_t(n) * per),
                          std::to_string(corners)}});
    starts.resize(std::size_t(n) + 1);
    for (std::uint32_t i = 0; i <= n; ++i)
        starts[i] = i * per;
    return starts;
}

GeogramFile withPoints(const std::vector<Vec3> &points)
{
    GeogramFile file;
    file.sets.push_back({kVertices, std::uint32_t(points.size())});
    std::vector<double> xyz;
    xyz.reserve(points.size() * 3);
    for (const Vec3 &p : points)
        xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    file.attributes.push_back(geogramAttribute(kVertices, "point", xyz, 3));
    return file;
}

// Geogram's local facets of a tet: facet i is opposite vertex i.
constexpr int kTetFacet[4][3] = {{1, 3, 2}, {0, 2, 3}, {3, 1, 0}, {0, 1, 2}};

} // namespace

std::vector<Vec3> geogramPoints(const GeogramFile &file, const std::string &where)
{
    const GeogramAttribute &a = required(file, kVertices, "point", 3, where);
    const std::vector<double> xyz = geogramDoubles(a, where);
    std::vector<Vec3> points(xyz.size() / 3);
    for (std::size_t i = 0; i < points.size(); ++i) {
        points[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        if (MessageText problem = pointProblem(points[i]); !problem.pattern.empty())
            fail(where, MessageText{
                            QT_TRANSLATE_NOOP("stratamesh::Core", "point %1 (numbered from 0): %2"),
                            {std::to_string(i)},
                            {std::move(problem)}});
    }
    return points;
}

std::vector<std::array<int, 2>> geogramEdges(const GeogramFile &file, std::size_t vertexCount,
                                             const std::string &where)
{
    std::vector<std::array<int, 2>> edges;
    if (itemCount(file, kEdges) == 0)
        return edges;
    const std::vector<std::uint32_t> ids = vertexIds(
        required(file, kEdges, "GEO::Mesh::edges::edge_vertex", 2, where), vertexCount, where);
    for (std::size_t i = 0; i + 1 < ids.size(); i += 2)
        edges.push_back({int(ids[i]), int(ids[i + 1])});
    return edges;
}

std::vector<Triangle> geogramTriangles(const GeogramFile &file, std::size_t vertexCount,
                                       const std::string &where)
{
    std::vector<Triangle> triangles;
    if (itemCount(file, kFacets) == 0)
        return triangles;
    const std::vector<std::uint32_t> corner = vertexIds(
        required(file, kFacetCorners, "GEO::Mesh::facet_corners::corner_vertex", 1, where),
        vertexCount, where);
    const std::vector<std::uint32_t> starts = itemStarts(
        file, kFacets, "GEO::Mesh::facets::facet_ptr", std::uint32_t(corner.size()), 3, where);
    for (std::size_t f = 0; f + 1 < starts.size(); ++f) {
        const std::uint32_t b = starts[f], e = starts[f + 1];
        if (e - b < 3)
            fail(where,
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "facet %1 has %2 corners"),
                             {std::to_string(f), std::to_string(e - b)}});
        for (std::uint32_t k = b + 1; k + 1 < e; ++k)
            triangles.push_back({int(corner[b]), int(corner[k]), int(corner[k + 1])});
    }
    return triangles;
}

std::vector<Cell> geogramCells(const GeogramFile &file, std::size_t vertexCount,
                               const std::string &where)
{
    std::vector<Cell> cells;
    const std::uint32_t n = itemCount(file, kCells);
    if (n == 0)
        return cells;
    const std::vector<std::uint32_t> corner =
        vertexIds(required(file, kCellCorners, "GEO::Mesh::cell_corners::corner_vertex", 1, where),
                  vertexCount, where);
    const std::vector<std::uint32_t> starts = itemStarts(file, kCells, "GEO::Mesh::cells::cell_ptr",
                                                         std::uint32_t(corner.size()), 4, where);
    std::string types(n, '\0'); // all tets unless cell_type says otherwise
    if (const GeogramAttribute *t = file.find(kCells, "GEO::Mesh::cells::cell_type")) {
        if (t->elementSize != 1 || t->dimension != 1)
            fail(where,
                 QT_TRANSLATE_NOOP("stratamesh::Core",
                                   "'GEO::Mesh::cells::cell_type' is not one char per cell"));
        types = t->data;
    }
    cells.reserve(n);
    for (std::uint32_t c = 0; c < n; ++c) {
        Cell cell;
        switch (types[c]) {
        case 0:
            cell.type = CellType::Tet;
            break;
        case 2:
            cell.type = CellType::Prism;
            break;
        case 3:
            cell.type = CellType::Pyramid;
            break;
        default:
            fail(where, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "cell %1 has geogram type %2 (only tets 0, "
                                                      "prisms 2 and pyramids 3 are supported)"),
                                    {std::to_string(c), std::to_string(int(types[c]))}});
        }
        if (starts[c + 1] - starts[c] != std::uint32_t(cell.size()))
            fail(where, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "cell %1 has %2 corners, its type needs %3"),
                                    {std::to_string(c), std::to_string(starts[c + 1] - starts[c]),
                                     std::to_string(cell.size())}});
        for (int k = 0; k < cell.size(); ++k)
            cell.nodes[k] = int(corner[starts[c] + k]);
        cells.push_back(cell);
    }
    return cells;
}

GeogramFile geogramPointMesh(const std::vector<Vec3> &points)
{
    return withPoints(points);
}

GeogramFile geogramLineMesh(const std::vector<Vec3> &points,
                            const std::vector<std::array<int, 2>> &edges)
{
    GeogramFile file = withPoints(points);
    file.sets.push_back({kEdges, std::uint32_t(edges.size())});
    std::vector<std::uint32_t> ids;
    for (const auto &e : edges)
        ids.insert(ids.end(), {std::uint32_t(e[0]), std::uint32_t(e[1])});
    file.attributes.push_back(geogramAttribute(kEdges, "GEO::Mesh::edges::edge_vertex", ids, 2));
    return file;
}

GeogramFile geogramSurfaceMesh(const std::vector<Vec3> &points,
                               const std::vector<Triangle> &triangles)
{
    GeogramFile file = withPoints(points);
    file.sets.push_back({kFacets, std::uint32_t(triangles.size())});
    file.sets.push_back({kFacetCorners, std::uint32_t(triangles.size() * 3)});
    std::vector<std::uint32_t> corner, adjacent(triangles.size() * 3, kNoId);
    std::map<std::pair<int, int>, std::uint32_t> edgeCorner; // directed edge → its corner
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            corner.push_back(std::uint32_t(triangles[t][k]));
            edgeCorner.emplace(std::make_pair(triangles[t][k], triangles[t][(k + 1) % 3]),
                               std::uint32_t(3 * t + k));
        }
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
            auto it = edgeCorner.find({b, a}); // consistently oriented neighbour
            if (it == edgeCorner.end())
                it = edgeCorner.find({a, b});
            if (it != edgeCorner.end() && it->second / 3 != t)
                adjacent[3 * t + k] = it->second / 3;
        }
    file.attributes.push_back(
        geogramAttribute(kFacetCorners, "GEO::Mesh::facet_corners::corner_vertex", corner, 1));
    file.attributes.push_back(geogramAttribute(
        kFacetCorners, "GEO::Mesh::facet_corners::corner_adjacent_facet", adjacent, 1));
    return file;
}

GeogramFile geogramVolumeMesh(const std::vector<Vec3> &points, const std::vector<Cell> &cells)
{
    GeogramFile file = withPoints(points);
    const bool allTets = std::all_of(cells.begin(), cells.end(),
                                     [](const Cell &c) { return c.type == CellType::Tet; });
    std::vector<std::uint32_t> corner, starts;
    std::string types;
    for (const Cell &c : cells) {
        starts.push_back(std::uint32_t(corner.size()));
        types.push_back(c.type == CellType::Tet ? 0 : c.type == CellType::Prism ? 2 : 3);
        for (int k = 0; k < c.size(); ++k)
            corner.push_back(std::uint32_t(c.nodes[k]));
    }
    file.sets.push_back({kCells, std::uint32_t(cells.size())});
    if (!allTets) {
        GeogramAttribute t;
        t.set = kCells;
        t.name = "GEO::Mesh::cells::cell_type";
        t.elementType = "char";
        t.elementSize = 1;
        t.dimension = 1;
        t.data = types;
        file.attributes.push_back(std::move(t));
        file.attributes.push_back(
            geogramAttribute(kCells, "GEO::Mesh::cells::cell_ptr", starts, 1));
    }
    file.sets.push_back({kCellCorners, std::uint32_t(corner.size())});
    file.attributes.push_back(
        geogramAttribute(kCellCorners, "GEO::Mesh::cell_corners::corner_vertex", corner, 1));
    // Geogram indexes cell facets like cell corners (cell_ptr). Tets get their neighbour across
    // each facet; other cells are left unconnected for Geogram to rebuild.
    std::vector<std::uint32_t> adjacent(corner.size(), kNoId);
    if (allTets) {
        std::map<std::array<int, 3>, std::uint32_t> facets;
        for (std::size_t c = 0; c < cells.size(); ++c)
            for (int f = 0; f < 4; ++f) {
                std::array<int, 3> key{cells[c].nodes[kTetFacet[f][0]],
                                       cells[c].nodes[kTetFacet[f][1]],
                                       cells[c].nodes[kTetFacet[f][2]]};
                std::sort(key.begin(), key.end());
                const auto [it, inserted] = facets.emplace(key, std::uint32_t(4 * c + f));
                if (!inserted) {
                    adjacent[4 * c + f] = it->second / 4;
                    adjacent[it->second] = std::uint32_t(c);
                }
            }
    }
    file.sets.push_back({kCellFacets, std::uint32_t(corner.size())});
    file.attributes.push_back(
        geogramAttribute(kCellFacets, "GEO::Mesh::cell_facets::adjacent_cell", adjacent, 1));
    return file;
}

} // namespace stratamesh
