#include "io/gmsh_reader.h"

#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/formats.h"
#include "io/gmsh_element_types.h"
#include "io/text_cursor.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace stratamesh {

namespace {

struct EntityInfo {
    std::vector<int> physicals;
    std::vector<int> bounding; // signed tags
};

struct RawElement {
    int dim = 0;
    int type = 0;
    int entity = 0;
    int physical = 0; // MSH 2.2 only; 0 = none
    std::size_t firstNode = 0;
};

int typeDimension(int type)
{
    switch (type) {
    case gmshPoint:
        return 0;
    case gmshLine:
        return 1;
    case gmshTriangle:
        return 2;
    default:
        return 3;
    }
}

class GmshParser {
public:
    explicit GmshParser(const std::string &path) : c(path) {}

    VolumeMesh run()
    {
        while (c.next()) {
            const std::vector<std::string_view> t = c.tokens();
            if (t.empty())
                continue;
            const std::string_view section = t[0];
            if (section == "$MeshFormat")
                readFormat();
            else if (section[0] != '$')
                c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                     "unexpected text outside a section: \"%1\""),
                                   {std::string(c.line())}});
            else if (major == 0)
                c.fail(
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "the file does not start with $MeshFormat: not a Gmsh mesh"));
            else if (section == "$PhysicalNames")
                readPhysicalNames();
            else if (section == "$Entities")
                readEntities();
            else if (section == "$Nodes")
                major == 4 ? readNodes41() : readNodes22();
            else if (section == "$Elements")
                major == 4 ? readElements41() : readElements22();
            else
                skipSection(std::string(section.substr(1)));
        }
        if (major == 0)
            c.fail(
                QT_TRANSLATE_NOOP("stratamesh::Core", "no $MeshFormat section: not a Gmsh mesh"));
        return build();
    }

private:
    void expectEnd(const char *end)
    {
        c.nextNonBlank(end);
        if (c.tokens().front() != end)
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "expected %1, found \"%2\""),
                               {end, std::string(c.line())}});
    }

    void skipSection(const std::string &name)
    {
        const std::string end = "$End" + name;
        const int start = c.lineNumber();
        while (c.next()) {
            const auto t = c.tokens();
            if (!t.empty() && t[0] == end)
                return;
        }
        throw FileError(c.path(), start,
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "section $%1 has no %2"),
                                    {name, end}});
    }

    void readFormat()
    {
        c.nextNonBlank("the format version");
        const auto t = c.tokens();
        if (t.size() < 3)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                     "expected \"version file-type data-size\" in $MeshFormat"));
        const std::string version(t[0]);
        if (version.rfind("4.1", 0) == 0)
            major = 4;
        else if (version[0] == '2')
            major = 2;
        else
            c.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "MSH version %1 is not supported (use 4.1 or 2.2)"),
                            {version}});
        if (t[1] != "0")
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                     "binary MSH files are not supported: save as ASCII"));
        expectEnd("$EndMeshFormat");
    }

    void readPhysicalNames()
    {
        c.nextNonBlank("the number of physical names");
        const int n = c.toCount(c.tokens().at(0), "the number of physical names", 6);
        for (int i = 0; i < n; ++i) {
            c.nextNonBlank("a physical name");
            const auto t = c.tokens();
            if (t.size() < 3)
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"dim tag \\\"name\\\"\""));
            const int dim = c.toInt(t[0], "a dimension"), tag = c.toInt(t[1], "a physical tag");
            const std::string_view line = c.line();
            const std::size_t open = line.find('"'), close = line.rfind('"');
            std::string name = open != std::string_view::npos && close > open
                                   ? std::string(line.substr(open + 1, close - open - 1))
                                   : std::string(t[2]);
            physicalNames[{dim, tag}] = name;
        }
        expectEnd("$EndPhysicalNames");
    }

    void readEntities()
    {
        if (major != 4)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "$Entities in an MSH 2 file"));
        c.nextNonBlank("the entity counts");
        const auto counts = c.tokens();
        if (counts.size() < 4)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                     "expected \"numPoints numCurves numSurfaces numVolumes\""));
        for (int dim = 0; dim < 4; ++dim) {
            const int n = c.toCount(counts[dim], "an entity count", 2);
            for (int i = 0; i < n; ++i) {
                c.nextNonBlank("an entity");
                const auto t = c.tokens();
                std::size_t k = 0;
                auto take = [&](const char *what) {
                    if (k >= t.size())
                        c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                             "entity line too short (missing %1)"),
                                           {what}});
                    return t[k++];
                };
                const int tag = c.toInt(take("the entity tag"), "an entity tag");
                for (int j = 0; j < (dim == 0 ? 3 : 6); ++j)
                    c.toDouble(take("a coordinate"), "a coordinate");
                EntityInfo &e = entities[{dim, tag}];
                const int nPhys =
                    c.toInt(take("the number of physical tags"), "a physical tag count");
                if (nPhys < 0)
                    c.fail(
                        QT_TRANSLATE_NOOP("stratamesh::Core", "negative number of physical tags"));
                for (int j = 0; j < nPhys; ++j)
                    e.physicals.push_back(
                        std::abs(c.toInt(take("a physical tag"), "a physical tag")));
                if (dim > 0) {
                    const int nBnd = c.toInt(take("the number of bounding entities"), "a count");
                    if (nBnd < 0)
                        c.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                                 "negative number of bounding entities"));
                    for (int j = 0; j < nBnd; ++j)
                        e.bounding.push_back(c.toInt(take("a bounding entity"), "an entity tag"));
                }
            }
        }
        expectEnd("$EndEntities");
    }

    void addNode(std::string_view tagText, const std::vector<std::string_view> &xyz)
    {
        const long long tag = c.toInt(tagText, "a node tag");
        if (xyz.size() < 3)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"x y z\""));
        const Vec3 p(c.toDouble(xyz[0], "x"), c.toDouble(xyz[1], "y"), c.toDouble(xyz[2], "z"));
        if (MessageText problem = pointProblem(p); !problem.pattern.empty())
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "node %1: %2"),
                               {std::to_string(tag)},
                               {std::move(problem)}});
        if (!nodeIndex.emplace(tag, static_cast<int>(points.size())).second)
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "node %1 is defined twice"),
                               {std::to_string(tag)}});
        points.push_back(p);
    }

    void readNodes22()
    {
        c.nextNonBlank("the number of nodes");
        // "tag x y z" and its end of line take at least 8 bytes.
        const int n = c.toCount(c.tokens().at(0), "the number of nodes", 8);
        for (int i = 0; i < n; ++i) {
            c.nextNonBlank("a node");
            auto t = c.tokens();
            if (t.size() < 4)
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"tag x y z\""));
            addNode(t[0], {t[1], t[2], t[3]});
        }
        expectEnd("$EndNodes");
    }

    void readNodes41()
    {
        c.nextNonBlank("the node counts");
        const auto h = c.tokens();
        if (h.size() < 4)
            c.fail(QT_TRANSLATE_NOOP(
                "stratamesh::Core", "expected \"numEntityBlocks numNodes minNodeTag maxNodeTag\""));
        const int blocks = c.toCount(h[0], "the number of node blocks", 8);
        const long long declared = c.toCount(h[1], "the number of nodes", 8);
        const int headerLine = c.lineNumber();
        long long total = 0;
        for (int b = 0; b < blocks; ++b) {
            c.nextNonBlank("a node block");
            const auto bh = c.tokens();
            if (bh.size() < 4)
                c.fail(QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "expected \"entityDim entityTag parametric numNodesInBlock\""));
            // A tag line and a coordinate line take at least 2 + 6 bytes.
            const int n = c.toCount(bh[3], "the number of nodes in the block", 8);
            total += n;
            std::vector<std::string> tags;
            tags.reserve(static_cast<std::size_t>(n));
            for (int i = 0; i < n; ++i) {
                c.nextNonBlank("a node tag");
                tags.emplace_back(c.tokens().at(0));
            }
            for (int i = 0; i < n; ++i) {
                c.nextNonBlank("node coordinates");
                addNode(tags[i], c.tokens());
            }
        }
        if (total != declared)
            throw FileError(
                c.path(), headerLine,
                MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "the $Nodes header declares %1 nodes, its blocks hold %2"),
                    {std::to_string(declared), std::to_string(total)}});
        expectEnd("$EndNodes");
    }

    void addElement(int dim, int type, int entity, int physical,
                    const std::vector<std::string_view> &t, std::size_t firstNodeToken)
    {
        const int k = gmshNodeCount(type);
        if (k == 0)
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "element type %1 (%2) is not supported: StrataMesh exchanges "
                                  "points, lines, triangles, tetrahedra, pyramids and prisms"),
                {std::to_string(type), gmshTypeName(type)}});
        if (t.size() < firstNodeToken + static_cast<std::size_t>(k))
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "a %1 needs %2 nodes"),
                               {gmshTypeName(type), std::to_string(k)}});
        RawElement e{dim, type, entity, physical, elementNodes.size()};
        for (int j = 0; j < k; ++j) {
            const long long tag =
                c.toInt(t[firstNodeToken + static_cast<std::size_t>(j)], "a node tag");
            auto it = nodeIndex.find(tag);
            if (it == nodeIndex.end())
                c.fail(
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "element uses node %1, which is not in $Nodes"),
                                {std::to_string(tag)}});
            for (std::size_t i = e.firstNode; i < elementNodes.size(); ++i)
                if (elementNodes[i] == it->second)
                    c.fail(MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core", "the %1 uses node %2 twice"),
                        {gmshTypeName(type), std::to_string(tag)}});
            elementNodes.push_back(it->second);
        }
        elements.push_back(e);
    }

    void readElements22()
    {
        c.nextNonBlank("the number of elements");
        const int n = c.toCount(c.tokens().at(0), "the number of elements", 8);
        for (int i = 0; i < n; ++i) {
            c.nextNonBlank("an element");
            const auto t = c.tokens();
            if (t.size() < 3)
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                         "expected \"tag type numTags tags... nodes...\""));
            const int type = c.toInt(t[1], "an element type");
            const int ntags = c.toInt(t[2], "a tag count");
            if (ntags < 0 || static_cast<std::size_t>(ntags) > t.size() - 3)
                c.fail(
                    QT_TRANSLATE_NOOP("stratamesh::Core", "element line too short for its tags"));
            const int physical = ntags > 0 ? c.toInt(t[3], "a physical tag") : 0;
            const int entity = ntags > 1 ? c.toInt(t[4], "an elementary tag") : 0;
            addElement(typeDimension(type), type, entity, physical, t,
                       3 + static_cast<std::size_t>(ntags));
        }
        expectEnd("$EndElements");
    }

    void readElements41()
    {
        c.nextNonBlank("the element counts");
        const auto h = c.tokens();
        if (h.size() < 4)
            c.fail(QT_TRANSLATE_NOOP(
                "stratamesh::Core",
                "expected \"numEntityBlocks numElements minElementTag maxElementTag\""));
        const int blocks = c.toCount(h[0], "the number of element blocks", 8);
        const long long declared = c.toCount(h[1], "the number of elements", 4);
        const int headerLine = c.lineNumber();
        long long total = 0;
        for (int b = 0; b < blocks; ++b) {
            c.nextNonBlank("an element block");
            const auto bh = c.tokens();
            if (bh.size() < 4)
                c.fail(QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "expected \"entityDim entityTag elementType numElementsInBlock\""));
            const int dim = c.toInt(bh[0], "a dimension"), entity = c.toInt(bh[1], "an entity tag");
            const int type = c.toInt(bh[2], "an element type");
            const int n = c.toCount(bh[3], "the number of elements in the block", 4);
            total += n;
            for (int i = 0; i < n; ++i) {
                c.nextNonBlank("an element");
                addElement(dim, type, entity, 0, c.tokens(), 1);
            }
        }
        if (total != declared)
            throw FileError(
                c.path(), headerLine,
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "the $Elements header declares %1 elements, its blocks hold %2"),
                            {std::to_string(declared), std::to_string(total)}});
        expectEnd("$EndElements");
    }

    int physicalOf(const RawElement &e) const
    {
        if (major != 4)
            return e.physical;
        auto it = entities.find({e.dim, e.entity});
        return it == entities.end() || it->second.physicals.empty() ? 0
                                                                    : it->second.physicals.front();
    }

    // Group keys of one dimension: physical tags when the file has some, entity tags otherwise.
    struct Grouping {
        bool byPhysical = false;
        std::vector<int> keys; // sorted
        int indexOf(int key) const
        {
            auto it = std::lower_bound(keys.begin(), keys.end(), key);
            return it != keys.end() && *it == key ? static_cast<int>(it - keys.begin()) : -1;
        }
    };

    Grouping grouping(int dim) const
    {
        std::set<int> physical, entity;
        for (const RawElement &e : elements)
            if (e.dim == dim) {
                if (const int p = physicalOf(e))
                    physical.insert(p);
                entity.insert(e.entity);
            }
        for (const auto &[key, info] : entities)
            if (key.first == dim) {
                physical.insert(info.physicals.begin(), info.physicals.end());
                entity.insert(key.second);
            }
        for (const auto &[key, name] : physicalNames)
            if (key.first == dim)
                physical.insert(key.second);
        Grouping g;
        g.byPhysical = !physical.empty();
        const std::set<int> &keys = g.byPhysical ? physical : entity;
        g.keys.assign(keys.begin(), keys.end());
        return g;
    }

    int groupOf(const Grouping &g, int dim, int entityTag, int physical) const
    {
        (void)dim;
        return g.byPhysical ? (physical ? g.indexOf(physical) : -1) : g.indexOf(entityTag);
    }

    std::vector<std::string> names(const Grouping &g, int dim, const char *kind) const
    {
        std::vector<std::string> out;
        for (int key : g.keys) {
            auto it = physicalNames.find({dim, key});
            out.push_back(g.byPhysical && it != physicalNames.end()
                              ? it->second
                              : std::string(kind) + "_" + std::to_string(key));
        }
        return out;
    }

    VolumeMesh build()
    {
        VolumeMesh mesh;
        mesh.name = fileStem(c.path());
        mesh.points = std::move(points);
        const Grouping lines = grouping(1), surfaces = grouping(2), regions = grouping(3);
        mesh.lineNames = names(lines, 1, "line");
        for (const std::string &name : names(surfaces, 2, "surface"))
            mesh.surfaces.push_back({name, name, FeatureType::Unknown});
        mesh.regionNames = names(regions, 3, "region");
        for (const RawElement &e : elements) {
            const int *n = elementNodes.data() + e.firstNode;
            const int physical = physicalOf(e);
            switch (e.type) {
            case gmshPoint:
                mesh.corners.push_back(n[0]);
                break;
            case gmshLine:
                mesh.edges.push_back({n[0], n[1]});
                mesh.edgeLine.push_back(groupOf(lines, 1, e.entity, physical));
                break;
            case gmshTriangle:
                mesh.triangles.push_back({n[0], n[1], n[2]});
                mesh.triangleSurface.push_back(groupOf(surfaces, 2, e.entity, physical));
                break;
            default: {
                Cell cell;
                cell.type = e.type == gmshTet       ? CellType::Tet
                            : e.type == gmshPyramid ? CellType::Pyramid
                                                    : CellType::Prism;
                std::copy(n, n + cell.size(), cell.nodes.begin());
                mesh.cells.push_back(cell);
                mesh.cellRegion.push_back(groupOf(regions, 3, e.entity, physical));
            }
            }
        }
        // Region sides from volume entity boundaries (MSH 4.1).
        std::vector<std::set<std::pair<int, bool>>> sides(mesh.regionNames.size());
        bool anySide = false;
        for (const auto &[key, info] : entities) {
            if (key.first != 3)
                continue;
            const int r = groupOf(regions, 3, key.second,
                                  info.physicals.empty() ? 0 : info.physicals.front());
            if (r < 0)
                continue;
            for (int b : info.bounding) {
                auto it = entities.find({2, std::abs(b)});
                const int phys = it == entities.end() || it->second.physicals.empty()
                                     ? 0
                                     : it->second.physicals.front();
                const int s = groupOf(surfaces, 2, std::abs(b), phys);
                if (s >= 0) {
                    sides[r].insert({s, b < 0});
                    anySide = true;
                }
            }
        }
        if (anySide)
            for (const auto &set : sides) {
                mesh.regionBoundaries.emplace_back();
                for (const auto &[s, positive] : set)
                    mesh.regionBoundaries.back().push_back({s, positive});
            }
        try {
            validateMesh(mesh);
        } catch (const InputError &e) {
            throw FileError(c.path(), 0, causeOf(e));
        }
        return mesh;
    }

    TextCursor c;
    int major = 0;
    std::map<std::pair<int, int>, std::string> physicalNames;
    std::map<std::pair<int, int>, EntityInfo> entities;
    std::unordered_map<long long, int> nodeIndex;
    std::vector<Vec3> points;
    std::vector<RawElement> elements;
    std::vector<int> elementNodes;
};

} // namespace

VolumeMesh readGmsh(const std::string &path)
{
    return GmshParser(path).run();
}

} // namespace stratamesh
