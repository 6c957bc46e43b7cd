#include "io/gmsh_writer.h"

#include "io/atomic_file.h"
#include "io/gmsh_element_types.h"
#include "io/number_text.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

namespace stratamesh {

namespace {

struct Entity {
    int dim = 0;
    int tag = 0;
    int physical = 0;                            // 0 = none
    std::map<int, std::vector<int>> nodesByType; // Gmsh element type -> flattened nodes
    std::vector<int> bounding;                   // signed tags of lower-dimension entities
    std::array<double, 6> box{0, 0, 0, 0, 0, 0};
    std::vector<int> nodes; // nodes classified on this entity
    std::size_t elementCount() const
    {
        std::size_t n = 0;
        for (const auto &[type, nodes] : nodesByType)
            n += nodes.size() / static_cast<std::size_t>(gmshNodeCount(type));
        return n;
    }
};

std::string quoted(const std::string &name)
{
    std::string out = "\"";
    for (char c : name)
        out += (c == '"' || c == '\n' || c == '\r') ? '\'' : c;
    return out + "\"";
}

void writeBox(std::ostream &out, const std::array<double, 6> &box)
{
    for (double v : box) {
        writeDouble(out, v);
        out << ' ';
    }
}

struct Layout {
    std::vector<Entity> entities[4];
    std::map<std::pair<int, int>, std::string> physicalNames; // (dim, tag) -> name
    std::size_t skipped = 0;
};

Layout buildLayout(const VolumeMesh &mesh, bool saveAll)
{
    Layout layout;
    // Dim 0: one point entity per distinct corner, all in one physical group.
    std::vector<int> corners = mesh.corners;
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    for (std::size_t i = 0; i < corners.size(); ++i) {
        Entity e;
        e.dim = 0;
        e.tag = static_cast<int>(i) + 1;
        e.physical = 1;
        e.nodesByType[gmshPoint].push_back(corners[i]);
        layout.entities[0].push_back(std::move(e));
    }
    if (!corners.empty())
        layout.physicalNames[{0, 1}] = "corners";

    // One entity per group; the untagged one last, with no physical group.
    auto makeGroups = [&](int dim, const std::vector<std::string> &names,
                          const std::vector<int> &groupOf, auto &&elementOf) {
        std::vector<Entity> &out = layout.entities[dim];
        const std::size_t base = out.size();
        for (std::size_t g = 0; g < names.size(); ++g) {
            Entity e;
            e.dim = dim;
            e.tag = static_cast<int>(g) + 1;
            e.physical = e.tag;
            layout.physicalNames[{dim, e.tag}] = names[g];
            out.push_back(std::move(e));
        }
        Entity untagged;
        untagged.dim = dim;
        untagged.tag = static_cast<int>(names.size()) + 1;
        for (std::size_t i = 0; i < groupOf.size(); ++i) {
            const auto [type, nodes] = elementOf(i);
            Entity *target =
                groupOf[i] >= 0 ? &out[base + static_cast<std::size_t>(groupOf[i])] : &untagged;
            if (groupOf[i] < 0 && !saveAll) {
                ++layout.skipped;
                continue;
            }
            std::vector<int> &list = target->nodesByType[type];
            list.insert(list.end(), nodes.begin(), nodes.end());
        }
        if (!untagged.nodesByType.empty())
            out.push_back(std::move(untagged));
    };
    using Nodes = std::vector<int>;
    makeGroups(1, mesh.lineNames, mesh.edgeLine, [&](std::size_t i) {
        return std::pair<int, Nodes>{gmshLine, Nodes{mesh.edges[i][0], mesh.edges[i][1]}};
    });
    makeGroups(
        2,
        [&] {
            std::vector<std::string> names;
            for (const MeshSurface &s : mesh.surfaces)
                names.push_back(s.name);
            return names;
        }(),
        mesh.triangleSurface,
        [&](std::size_t i) {
            const Triangle &t = mesh.triangles[i];
            return std::pair<int, Nodes>{gmshTriangle, Nodes{t[0], t[1], t[2]}};
        });
    makeGroups(3, mesh.regionNames, mesh.cellRegion, [&](std::size_t i) {
        const Cell &c = mesh.cells[i];
        return std::pair<int, Nodes>{gmshTypeOf(c.type),
                                     Nodes(c.nodes.begin(), c.nodes.begin() + c.size())};
    });
    // Regions of a surface model are empty volumes bounded by their surfaces; the boundary sign
    // is + when the surface normal points out of the region.
    for (std::size_t r = 0; r < mesh.regionBoundaries.size(); ++r)
        for (const RegionSide &side : mesh.regionBoundaries[r])
            layout.entities[3][r].bounding.push_back(side.positive ? -(side.surface + 1)
                                                                   : side.surface + 1);
    return layout;
}

// Each node goes to the lowest-dimension entity holding it; unused nodes to a spare volume entity.
void classifyNodes(const VolumeMesh &mesh, Layout &layout)
{
    const std::size_t n = mesh.points.size();
    std::vector<std::pair<int, int>> owner(n, {4, -1}); // (dim, entity index)
    for (int dim = 0; dim < 4; ++dim)
        for (std::size_t e = 0; e < layout.entities[dim].size(); ++e)
            for (const auto &[type, nodes] : layout.entities[dim][e].nodesByType)
                for (int p : nodes)
                    if (dim < owner[p].first)
                        owner[p] = {dim, static_cast<int>(e)};
    bool unused = false;
    for (const auto &o : owner)
        unused |= o.second < 0;
    if (unused) {
        std::vector<Entity> &volumes = layout.entities[3];
        int tag = 0;
        for (const Entity &e : volumes)
            tag = std::max(tag, e.tag);
        Entity spare;
        spare.dim = 3;
        spare.tag = tag + 1;
        volumes.push_back(std::move(spare));
        for (auto &o : owner)
            if (o.second < 0)
                o = {3, static_cast<int>(volumes.size()) - 1};
    }
    for (std::size_t p = 0; p < n; ++p)
        layout.entities[owner[p].first][owner[p].second].nodes.push_back(static_cast<int>(p));
}

void computeBoxes(const VolumeMesh &mesh, Layout &layout)
{
    auto grow = [](std::array<double, 6> &box, bool &empty, const std::array<double, 6> &other) {
        for (int k = 0; k < 3; ++k) {
            box[k] = empty ? other[k] : std::min(box[k], other[k]);
            box[k + 3] = empty ? other[k + 3] : std::max(box[k + 3], other[k + 3]);
        }
        empty = false;
    };
    for (int dim = 0; dim < 4; ++dim)
        for (Entity &e : layout.entities[dim]) {
            bool empty = true;
            for (const auto &[type, nodes] : e.nodesByType)
                for (int p : nodes) {
                    const Vec3 &x = mesh.points[p];
                    grow(e.box, empty, {x.x(), x.y(), x.z(), x.x(), x.y(), x.z()});
                }
            for (int p : e.nodes) {
                const Vec3 &x = mesh.points[p];
                grow(e.box, empty, {x.x(), x.y(), x.z(), x.x(), x.y(), x.z()});
            }
            if (dim == 3)
                for (int b : e.bounding) {
                    const int s = std::abs(b) - 1;
                    if (s >= 0 && s < static_cast<int>(layout.entities[2].size())
                        && !layout.entities[2][s].nodesByType.empty())
                        grow(e.box, empty, layout.entities[2][s].box);
                }
        }
}

void writePhysicalNames(std::ostream &out, const Layout &layout)
{
    if (layout.physicalNames.empty())
        return;
    out << "$PhysicalNames\n" << layout.physicalNames.size() << '\n';
    for (const auto &[key, name] : layout.physicalNames)
        out << key.first << ' ' << key.second << ' ' << quoted(name) << '\n';
    out << "$EndPhysicalNames\n";
}

void writeNodeCoordinates(std::ostream &out, const Vec3 &p)
{
    writeDouble(out, p.x());
    out << ' ';
    writeDouble(out, p.y());
    out << ' ';
    writeDouble(out, p.z());
    out << '\n';
}

std::size_t write41(std::ostream &out, const VolumeMesh &mesh, const Layout &layout)
{
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    writePhysicalNames(out, layout);
    out << "$Entities\n";
    out << layout.entities[0].size() << ' ' << layout.entities[1].size() << ' '
        << layout.entities[2].size() << ' ' << layout.entities[3].size() << '\n';
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim]) {
            out << e.tag << ' ';
            if (dim == 0) {
                for (int k = 0; k < 3; ++k) {
                    writeDouble(out, e.box[k]);
                    out << ' ';
                }
            } else {
                writeBox(out, e.box);
            }
            out << (e.physical ? 1 : 0);
            if (e.physical)
                out << ' ' << e.physical;
            if (dim > 0) {
                out << ' ' << e.bounding.size();
                for (int b : e.bounding)
                    out << ' ' << b;
            }
            out << '\n';
        }
    out << "$EndEntities\n";

    std::size_t blocks = 0;
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim])
            blocks += e.nodes.empty() ? 0 : 1;
    const std::size_t n = mesh.points.size();
    out << "$Nodes\n" << blocks << ' ' << n << ' ' << (n ? 1 : 0) << ' ' << n << '\n';
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim]) {
            if (e.nodes.empty())
                continue;
            out << dim << ' ' << e.tag << " 0 " << e.nodes.size() << '\n';
            for (int p : e.nodes)
                out << p + 1 << '\n';
            for (int p : e.nodes)
                writeNodeCoordinates(out, mesh.points[p]);
        }
    out << "$EndNodes\n";

    std::size_t elementBlocks = 0, elements = 0;
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim]) {
            elementBlocks += e.nodesByType.size();
            elements += e.elementCount();
        }
    out << "$Elements\n"
        << elementBlocks << ' ' << elements << ' ' << (elements ? 1 : 0) << ' ' << elements << '\n';
    std::size_t tag = 1;
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim])
            for (const auto &[type, nodes] : e.nodesByType) {
                const std::size_t k = static_cast<std::size_t>(gmshNodeCount(type));
                out << dim << ' ' << e.tag << ' ' << type << ' ' << nodes.size() / k << '\n';
                for (std::size_t i = 0; i < nodes.size(); i += k) {
                    out << tag++;
                    for (std::size_t j = 0; j < k; ++j)
                        out << ' ' << nodes[i + j] + 1;
                    out << '\n';
                }
            }
    out << "$EndElements\n";
    return elements;
}

std::size_t write22(std::ostream &out, const VolumeMesh &mesh, const Layout &layout)
{
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
    writePhysicalNames(out, layout);
    out << "$Nodes\n" << mesh.points.size() << '\n';
    for (std::size_t p = 0; p < mesh.points.size(); ++p) {
        out << p + 1 << ' ';
        writeNodeCoordinates(out, mesh.points[p]);
    }
    out << "$EndNodes\n";
    std::size_t elements = 0;
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim])
            elements += e.elementCount();
    out << "$Elements\n" << elements << '\n';
    std::size_t tag = 1;
    for (int dim = 0; dim < 4; ++dim)
        for (const Entity &e : layout.entities[dim])
            for (const auto &[type, nodes] : e.nodesByType) {
                const std::size_t k = static_cast<std::size_t>(gmshNodeCount(type));
                for (std::size_t i = 0; i < nodes.size(); i += k) {
                    out << tag++ << ' ' << type << " 2 " << e.physical << ' ' << e.tag;
                    for (std::size_t j = 0; j < k; ++j)
                        out << ' ' << nodes[i + j] + 1;
                    out << '\n';
                }
            }
    out << "$EndElements\n";
    return elements;
}

} // namespace

GmshWriteResult writeGmsh(const VolumeMesh &mesh, const std::string &path,
                          const GmshWriteOptions &options)
{
    validateMesh(mesh);
    Layout layout = buildLayout(mesh, options.saveAll);
    classifyNodes(mesh, layout);
    computeBoxes(mesh, layout);
    GmshWriteResult result;
    result.untaggedSkipped = layout.skipped;
    writeTextFileAtomically(path, [&](std::ostream &out) {
        result.elementsWritten = options.version == GmshWriteOptions::Version::V41
                                     ? write41(out, mesh, layout)
                                     : write22(out, mesh, layout);
    });
    return result;
}

} // namespace stratamesh
