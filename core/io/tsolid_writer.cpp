#include "io/tsolid_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/atomic_file.h"
#include "io/gocad_writer_common.h"

#include <map>

namespace stratamesh {

namespace {

std::string typeWord(FeatureType type)
{
    return type == FeatureType::Unknown ? "no_geological_feature" : gocadTypeName(type);
}

std::string headerValue(const std::string &text)
{
    std::string out;
    for (char c : text)
        out += (c == '\n' || c == '\r' || c == '}') ? '_' : c;
    return out;
}

} // namespace

void writeGocadTSolid(const VolumeMesh &mesh, const std::string &path)
{
    validateMesh(mesh);
    if (mesh.cells.empty())
        throw InputError(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "a TSolid needs tetrahedra: the mesh '%1' has no cell"),
                        {mesh.name}});
    const std::size_t others = mesh.cells.size() - mesh.countCells(CellType::Tet);
    if (others > 0)
        throw InputError(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "a TSolid holds tetrahedra only: the mesh '%1' has %2 "
                                          "prisms and %3 pyramids (use .vtu or .msh)"),
                        {mesh.name, std::to_string(mesh.countCells(CellType::Prism)),
                         std::to_string(mesh.countCells(CellType::Pyramid))}});

    // Regions in order, untagged cells last in a volume of their own.
    std::vector<std::string> volumeNames = mesh.regionNames;
    std::vector<std::vector<int>> cellsOf(volumeNames.size());
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const int r = mesh.cellRegion[c];
        if (r < 0) {
            if (cellsOf.size() == mesh.regionNames.size()) {
                cellsOf.emplace_back();
                volumeNames.push_back("untagged");
            }
            cellsOf.back().push_back(static_cast<int>(c));
        } else {
            cellsOf[r].push_back(static_cast<int>(c));
        }
    }
    // Surfaces grouped by feature, in order of first appearance; TFACE ids follow that order.
    std::vector<std::string> featureOrder;
    std::map<std::string, std::vector<int>> byFeature;
    for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
        const MeshSurface &surface = mesh.surfaces[s];
        const std::string feature =
            surface.featureName.empty() ? surface.name : surface.featureName;
        if (!byFeature.count(feature))
            featureOrder.push_back(feature);
        byFeature[feature].push_back(static_cast<int>(s));
    }
    std::vector<int> faceId(mesh.surfaces.size(), 0);
    int nextFace = 1;
    for (const std::string &f : featureOrder)
        for (int s : byFeature[f])
            faceId[s] = nextFace++;
    std::vector<std::vector<int>> trianglesOf(mesh.surfaces.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (mesh.triangleSurface[t] >= 0)
            trianglesOf[mesh.triangleSurface[t]].push_back(static_cast<int>(t));
    const std::vector<std::vector<RegionSide>> sides =
        mesh.regionBoundaries.empty() ? regionSidesFromCells(mesh) : mesh.regionBoundaries;

    writeTextFileAtomically(path, [&](std::ostream &out) {
        out << "GOCAD TSolid 1\nHEADER {\nname: "
            << headerValue(mesh.name.empty() ? "mesh" : mesh.name) << '\n';
        for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
            out << "*tface*" << faceId[s] << "*name: " << headerValue(mesh.surfaces[s].name)
                << '\n';
            out << "*tface*" << faceId[s] << "*type: " << typeWord(mesh.surfaces[s].type) << '\n';
        }
        out << "}\n";
        writeGocadCoordinateSystem(out, mesh.zPositiveDepth);
        std::vector<int> firstId(mesh.points.size(), 0), volumeOf(mesh.points.size(), -1);
        std::vector<int> idHere(mesh.points.size(), 0);
        int nextId = 1;
        for (std::size_t v = 0; v < cellsOf.size(); ++v) {
            out << "TVOLUME " << gocadToken(volumeNames[v]) << '\n';
            const int volume = static_cast<int>(v);
            auto declare = [&](int p) {
                if (volumeOf[p] == volume)
                    return;
                if (volumeOf[p] < 0) {
                    firstId[p] = nextId;
                    out << "VRTX " << nextId << ' ';
                    writeGocadPoint(out, mesh.points[p], mesh.zPositiveDepth);
                    out << '\n';
                } else {
                    out << "ATOM " << nextId << ' ' << firstId[p] << '\n';
                }
                idHere[p] = nextId++;
                volumeOf[p] = volume;
            };
            for (int c : cellsOf[v])
                for (int k = 0; k < 4; ++k)
                    declare(mesh.cells[c].nodes[k]);
            if (v + 1 == cellsOf.size()) // points no tet uses still belong to the mesh
                for (std::size_t p = 0; p < mesh.points.size(); ++p)
                    if (volumeOf[p] < 0)
                        declare(static_cast<int>(p));
            for (int c : cellsOf[v]) {
                const Cell &cell = mesh.cells[c];
                out << "TETRA " << idHere[cell.nodes[0]] << ' ' << idHere[cell.nodes[1]] << ' '
                    << idHere[cell.nodes[2]] << ' ' << idHere[cell.nodes[3]] << '\n';
            }
        }
        out << "MODEL\n";
        for (const std::string &f : featureOrder) {
            out << "SURFACE " << gocadToken(f) << '\n';
            for (int s : byFeature[f]) {
                out << "TFACE " << faceId[s] << '\n';
                if (!trianglesOf[s].empty()) {
                    const Triangle &k = mesh.triangles[trianglesOf[s].front()];
                    out << "KEYVERTICES " << firstId[k[0]] << ' ' << firstId[k[1]] << ' '
                        << firstId[k[2]] << '\n';
                }
                for (int t : trianglesOf[s]) {
                    const Triangle &tri = mesh.triangles[t];
                    out << "TRGL " << firstId[tri[0]] << ' ' << firstId[tri[1]] << ' '
                        << firstId[tri[2]] << '\n';
                }
            }
        }
        for (std::size_t r = 0; r < mesh.regionNames.size() && r < sides.size(); ++r)
            if (!sides[r].empty())
                out << "MODEL_REGION " << gocadToken(mesh.regionNames[r]) << ' '
                    << (sides[r].front().positive ? "+" : "-") << faceId[sides[r].front().surface]
                    << '\n';
        out << "END\n";
    });
}

} // namespace stratamesh
