#include "io/ringmesh_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/atomic_file.h"
#include "io/geogram_mesh.h"
#include "io/zip_archive.h"
#include "mesh/model_conversion.h"
#include "model/feature_type.h"
#include "model/topology.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>

namespace stratamesh {

namespace {

std::string field(const std::string &name)
{
    if (name.empty())
        return "No_name";
    std::string out = name;
    for (char &c : out)
        if (std::isspace(static_cast<unsigned char>(c)))
            c = '_';
    return out;
}

// RINGMesh's words for the geological features (GeoModelGeologicalEntity::geol_name) are Gocad's,
// except for a surface of no feature.
std::string ringMeshFeature(FeatureType type)
{
    return type == FeatureType::Unknown ? "no_geological_feature" : gocadTypeName(type);
}

struct GmLine {
    std::vector<int> vertices; // global ids, first and last are the corners
    std::array<int, 2> corners{-1, -1};
};

struct GmRegionCells {
    std::vector<Vec3> points;
    std::vector<Cell> cells;
};

class Writer {
public:
    Writer(const Model &model, std::vector<GmRegionCells> regionCells)
        : m(model.hasTopology() ? model : recoverTopology(model)),
          m_regionCells(std::move(regionCells))
    {
        if (m.surfaces.empty())
            throw InputError(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "the model '%1' has no surface to write"),
                {m.name}});
        for (const Surface &s : m.surfaces)
            if (s.triangles.empty())
                throw InputError(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core", "surface '%1' has no triangle"),
                    {s.name}});
        buildLines();
        buildInterfaces();
        countSidesOnLines();
    }

    void write(const std::string &path)
    {
        writeFileAtomically(path, [&](const std::string &temporary) {
            ZipWriter zip(temporary);
            zip.add("mesh_entities.txt", meshEntities());
            zip.add("geological_entities.txt", geologicalEntities());
            std::map<std::string, GeogramFile> files; // sorted by name, as RINGMesh does
            for (std::size_t c = 0; c < m_cornerVertex.size(); ++c)
                files.emplace("Corner_" + std::to_string(c) + ".geogram",
                              geogramPointMesh({m.vertices[m_cornerVertex[c]]}));
            for (std::size_t l = 0; l < m_lines.size(); ++l)
                files.emplace("Line_" + std::to_string(l) + ".geogram", lineMesh(m_lines[l]));
            for (std::size_t s = 0; s < m.surfaces.size(); ++s)
                files.emplace("Surface_" + std::to_string(s) + ".geogram",
                              geogramSurfaceMesh(m.surfaces[s].vertices, m.surfaces[s].triangles));
            for (std::size_t r = 0; r < m_regionCells.size() && r < m.regions.size(); ++r)
                if (!m_regionCells[r].cells.empty())
                    files.emplace(
                        "Region_" + std::to_string(r) + ".geogram",
                        geogramVolumeMesh(m_regionCells[r].points, m_regionCells[r].cells));
            for (auto &[name, file] : files) {
                file.comments.push_back("written by StrataMesh");
                zip.add(name, writeGeogramFile(file, path + ":" + name));
            }
            zip.close();
        });
    }

private:
    void buildLines()
    {
        m_cornerVertex.reserve(m.corners.size());
        for (const Corner &c : m.corners)
            m_cornerVertex.push_back(c.vertex);
        for (const Line &line : m.lines) {
            GmLine l;
            l.vertices = line.vertices;
            if (line.closed || line.corners[0] < 0) {
                // RINGMesh lines always end at two corners: close the loop on a new one.
                const int corner = int(m_cornerVertex.size());
                m_cornerVertex.push_back(line.vertices.front());
                l.vertices.push_back(line.vertices.front());
                l.corners = {corner, corner};
            } else {
                l.corners = line.corners;
            }
            m_lines.push_back(std::move(l));
        }
    }

    // RINGMesh lists a line twice in the boundaries of a surface lying on both of its sides (an
    // internal border, GeoModelMeshEntity::is_inside_border): count the surface's triangles along
    // the line's first edge.
    void countSidesOnLines()
    {
        std::map<std::pair<int, int>, int> firstEdge; // global vertices → line
        for (std::size_t l = 0; l < m.lines.size(); ++l) {
            const std::vector<int> &v = m.lines[l].vertices;
            if (v.size() >= 2)
                firstEdge.emplace(std::minmax(v[0], v[1]), int(l));
        }
        m_sidesOnLine.resize(m.surfaces.size());
        for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
            const std::vector<int> &global = m.surfaceVertexToGlobal[s];
            for (const Triangle &t : m.surfaces[s].triangles)
                for (int k = 0; k < 3; ++k) {
                    const auto it =
                        firstEdge.find(std::minmax(global[t[k]], global[t[(k + 1) % 3]]));
                    if (it != firstEdge.end())
                        ++m_sidesOnLine[s][it->second];
                }
            for (int l : m.surfaces[s].lines) {
                int &sides = m_sidesOnLine[s][l];
                sides = sides >= 2 ? 2 : 1;
            }
        }
    }

    GeogramFile lineMesh(const GmLine &line) const
    {
        std::vector<Vec3> points;
        std::vector<std::array<int, 2>> edges;
        for (std::size_t i = 0; i < line.vertices.size(); ++i) {
            points.push_back(m.vertices[line.vertices[i]]);
            if (i > 0)
                edges.push_back({int(i - 1), int(i)});
        }
        return geogramLineMesh(points, edges);
    }

    // One interface per (feature name, type), in the order of first appearance.
    void buildInterfaces()
    {
        std::map<std::pair<std::string, FeatureType>, int> index;
        m_surfaceInterface.resize(m.surfaces.size());
        for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
            const Surface &surface = m.surfaces[s];
            const std::string name =
                surface.featureName.empty() ? surface.name : surface.featureName;
            const auto [it, inserted] =
                index.emplace(std::make_pair(name, surface.type), int(m_interfaces.size()));
            if (inserted)
                m_interfaces.push_back({name, surface.type, {}});
            m_interfaces[it->second].surfaces.push_back(int(s));
            m_surfaceInterface[s] = it->second;
        }
    }

    std::vector<RegionSide> universe() const
    {
        if (!m.universe.empty())
            return m.universe;
        std::map<int, std::set<bool>> claimed;
        for (const Region &r : m.regions)
            for (const RegionSide &side : r.boundaries)
                claimed[side.surface].insert(side.positive);
        std::vector<RegionSide> out;
        for (const auto &[surface, signs] : claimed)
            if (signs.size() == 1)
                out.push_back({surface, !*signs.begin()});
        return out;
    }

    static void writeSides(std::ostream &out, const std::vector<RegionSide> &sides)
    {
        for (const RegionSide &side : sides)
            out << (side.positive ? "+" : "-") << side.surface << " ";
        out << "\n";
    }

    std::string meshEntities() const
    {
        std::ostringstream out;
        out << "Dimension 3\nVersion 2\nGeoModel name " << field(m.name) << "\n";
        out << "Nb Corner " << m_cornerVertex.size() << "\nNb Line " << m_lines.size()
            << "\nNb Surface " << m.surfaces.size() << "\nNb Region " << m.regions.size() << "\n";
        for (std::size_t c = 0; c < m_cornerVertex.size(); ++c)
            out << "Corner " << c << " No_name GeogramPointSetMesh\nboundary \n";
        for (std::size_t l = 0; l < m_lines.size(); ++l) {
            const std::string name = l < m.lines.size() ? m.lines[l].name : std::string();
            out << "Line " << l << " " << field(name) << " GeogramLineMesh\nboundary "
                << m_lines[l].corners[0] << " " << m_lines[l].corners[1] << " \n";
        }
        for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
            out << "Surface " << s << " " << field(m.surfaces[s].name)
                << " GeogramSurfaceMesh\nboundary ";
            for (int l : m.surfaces[s].lines)
                for (int k = 0; k < m_sidesOnLine[s].at(l); ++k)
                    out << l << " ";
            out << "\n";
        }
        for (std::size_t r = 0; r < m.regions.size(); ++r) {
            out << "Region " << r << " " << field(m.regions[r].name) << " GeogramVolumeMesh\n";
            writeSides(out, m.regions[r].boundaries);
        }
        out << "Universe \n";
        writeSides(out, universe());
        return out.str();
    }

    std::string geologicalEntities() const
    {
        // Contacts: the lines touching one set of interfaces, named after them.
        std::map<std::set<int>, std::vector<int>> contactLines;
        std::vector<std::set<int>> order;
        for (std::size_t l = 0; l < m.lines.size(); ++l) {
            std::set<int> key;
            for (int s : m.lines[l].surfaces)
                key.insert(m_surfaceInterface[s]);
            auto [it, inserted] = contactLines.emplace(key, std::vector<int>{});
            if (inserted)
                order.push_back(key);
            it->second.push_back(int(l));
        }
        std::ostringstream out;
        out << "Nb Interface " << m_interfaces.size() << "\nNb Contact " << order.size() << "\n";
        if (!m.layers.empty())
            out << "Nb Layer " << m.layers.size() << "\n";
        for (std::size_t i = 0; i < m_interfaces.size(); ++i) {
            out << "Interface " << i << " " << field(m_interfaces[i].name) << " "
                << ringMeshFeature(m_interfaces[i].type) << "\n";
            for (int s : m_interfaces[i].surfaces)
                out << s << " ";
            out << "\n";
        }
        for (std::size_t c = 0; c < order.size(); ++c) {
            std::string name = "contact";
            for (int i : order[c])
                name += "_" + field(m_interfaces[i].name);
            out << "Contact " << c << " " << name << " no_geological_feature\n";
            for (int l : contactLines[order[c]])
                out << l << " ";
            out << "\n";
        }
        for (std::size_t i = 0; i < m.layers.size(); ++i) {
            out << "Layer " << i << " " << field(m.layers[i].name) << " no_geological_feature\n";
            for (int r : m.layers[i].regions)
                out << r << " ";
            out << "\n";
        }
        return out.str();
    }

    struct Interface {
        std::string name;
        FeatureType type;
        std::vector<int> surfaces;
    };

    const Model m;
    std::vector<GmRegionCells> m_regionCells;
    std::vector<int> m_cornerVertex; // global vertex of each written corner
    std::vector<GmLine> m_lines;
    std::vector<Interface> m_interfaces;
    std::vector<int> m_surfaceInterface;
    std::vector<std::map<int, int>>
        m_sidesOnLine; // per surface: line → 1, or 2 for an internal border
};

} // namespace

void writeRingMeshModel(const Model &model, const std::string &path)
{
    Writer(model, {}).write(path);
}

void writeRingMeshVolume(const VolumeMesh &mesh, const std::string &path)
{
    validateMesh(mesh);
    const Model model = modelFromMesh(mesh);
    std::vector<GmRegionCells> regions(mesh.regionNames.size());
    std::vector<std::map<int, int>> local(mesh.regionNames.size()); // mesh point → region vertex
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const int r = mesh.cellRegion[c];
        if (r < 0)
            throw InputError(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "cell %1 has no region: a GeoModel stores cells per region"),
                {std::to_string(c)}});
        Cell cell = mesh.cells[c];
        for (int k = 0; k < cell.size(); ++k) {
            const auto [it, inserted] =
                local[r].emplace(cell.nodes[k], int(regions[r].points.size()));
            if (inserted)
                regions[r].points.push_back(mesh.points[cell.nodes[k]]);
            cell.nodes[k] = it->second;
        }
        regions[r].cells.push_back(cell);
    }
    Writer(model, std::move(regions)).write(path);
}

} // namespace stratamesh
