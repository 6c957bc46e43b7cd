// The exchange mesh: node-order conventions (signed volumes of Gmsh's reference cells), outward
// faces, region sides recovered from cells, validation, and Model <-> mesh conversion.
#include "../io/test_roundtrip_meshes.h"
#include "common/error.h"
#include "mesh/model_conversion.h"
#include "mesh/volume_mesh.h"
#include "model/synthetic_models.h"
#include "model/topology.h"

#include <Eigen/Geometry>

#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

VolumeMesh referenceCells()
{
    // Gmsh reference elements (formats.md §2.5).
    VolumeMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; // tet 0-3
    m.points.insert(m.points.end(),
                    {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}); // pyramid 4-8
    m.points.insert(
        m.points.end(),
        {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}); // prism 9-14
    m.cells = {Cell::tet(0, 1, 2, 3), Cell::pyramid(4, 5, 6, 7, 8),
               Cell::prism(9, 10, 11, 12, 13, 14)};
    m.cellRegion = {-1, -1, -1};
    return m;
}

Vec3 normal(const VolumeMesh &m, const Triangle &t)
{
    return (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
}

Vec3 centroid(const VolumeMesh &m, const Cell &c)
{
    Vec3 g = Vec3::Zero();
    for (int k = 0; k < c.size(); ++k)
        g += m.points[c.nodes[k]];
    return g / c.size();
}

} // namespace

class TestVolumeMesh : public QObject {
    Q_OBJECT

private slots:
    void referenceCellsArePositive()
    {
        const VolumeMesh m = referenceCells();
        QCOMPARE(signedVolume(m, m.cells[0]), 1.0 / 6.0);
        QVERIFY(std::abs(signedVolume(m, m.cells[1]) - 4.0 / 3.0) < 1e-15);
        QVERIFY(std::abs(signedVolume(m, m.cells[2]) - 1.0) < 1e-15);
        // The opposite orientations are negative.
        QVERIFY(signedVolume(m, Cell::tet(0, 2, 1, 3)) < 0);
        QVERIFY(signedVolume(m, Cell::pyramid(4, 7, 6, 5, 8)) < 0);
        QVERIFY(signedVolume(m, Cell::prism(9, 11, 10, 12, 14, 13)) < 0);
    }

    // Unused points go; the cells, triangles, edges and corners keep their coordinates.
    void unusedPointsAreDropped()
    {
        VolumeMesh m = referenceCells();
        m.points.insert(m.points.begin() + 2, Vec3(9, 9, 9)); // unused, between used ones
        for (Cell &c : m.cells)
            for (int k = 0; k < c.size(); ++k)
                c.nodes[k] += c.nodes[k] >= 2 ? 1 : 0;
        m.points.push_back(Vec3(7, 7, 7)); // unused, last
        m.triangles = {{0, 1, 3}};
        m.triangleSurface = {-1};
        m.edges = {{5, 6}};
        m.edgeLine = {-1};
        m.points.push_back(Vec3(5, 5, 5)); // a corner only: kept
        m.corners = {int(m.points.size()) - 1};
        const VolumeMesh before = m;
        dropUnusedPoints(m);
        QCOMPARE(m.points.size(), before.points.size() - 2);
        validateMesh(m);
        for (std::size_t c = 0; c < m.cells.size(); ++c)
            for (int k = 0; k < m.cells[c].size(); ++k)
                QCOMPARE(m.points[m.cells[c].nodes[k]], before.points[before.cells[c].nodes[k]]);
        QCOMPARE(m.points[m.triangles[0][2]], before.points[before.triangles[0][2]]);
        QCOMPARE(m.points[m.edges[0][1]], before.points[before.edges[0][1]]);
        QCOMPARE(m.points[m.corners[0]], Vec3(5, 5, 5));
        for (const Vec3 &p : m.points)
            QVERIFY(p != Vec3(9, 9, 9) && p != Vec3(7, 7, 7));
        QCOMPARE(signedVolume(m, m.cells[2]), signedVolume(before, before.cells[2]));
    }

    // A prism with one warped quad and a pyramid on that quad: their volumes add up to what the
    // pair covers, whatever diagonal either cell's node order would pick.
    void warpedQuadVolumesAddUp()
    {
        const double t = 0.3; // moves top node 4 along the planes of the top and of quad 1 2 5 4
        VolumeMesh m;
        m.points = {{0, 0, 0},     {1, 0, 0}, {0, 1, 0},       {0, 0, 1},
                    {1 - t, t, 1}, {0, 1, 1}, {0.5, -0.5, 0.5}};
        const Cell prism = Cell::prism(0, 1, 2, 3, 4, 5), pyramid = Cell::pyramid(0, 1, 4, 3, 6);
        // The closed triangulated boundary of the pair: the prism's planar faces and the sides
        // of the pyramid, outward.
        const std::vector<Triangle> boundary = {{0, 2, 1}, {3, 4, 5}, {1, 2, 5}, {1, 5, 4},
                                                {2, 0, 3}, {2, 3, 5}, {0, 1, 6}, {1, 4, 6},
                                                {4, 3, 6}, {3, 0, 6}};
        double covered = 0.0;
        for (const Triangle &f : boundary)
            covered +=
                m.points[f[0]].dot(m.points[f[1]].cross(m.points[f[2]])) / 6.0; // cone from 0
        const double sum = signedVolume(m, prism) + signedVolume(m, pyramid);
        QVERIFY2(std::abs(sum - covered) < 1e-14, qPrintable(QString::number(sum - covered)));
        // The same cells numbered from another corner: the same volumes.
        QVERIFY(std::abs(signedVolume(m, Cell::prism(1, 2, 0, 4, 5, 3)) - signedVolume(m, prism))
                < 1e-14);
        QVERIFY(std::abs(signedVolume(m, Cell::pyramid(1, 4, 3, 0, 6)) - signedVolume(m, pyramid))
                < 1e-14);
    }

    void outwardFacesPointOut()
    {
        const VolumeMesh m = test::hybridMesh();
        for (const Cell &c : m.cells) {
            QVERIFY(signedVolume(m, c) > 0);
            const Vec3 g = centroid(m, c);
            const std::vector<Triangle> faces = outwardTriangleFaces(c);
            QCOMPARE(int(faces.size()), c.type == CellType::Prism ? 2 : 4);
            for (const Triangle &f : faces)
                QVERIFY(normal(m, f).dot(m.points[f[0]] - g) > 0);
        }
    }

    void regionSidesFromCells()
    {
        const VolumeMesh m = test::hybridMesh();
        const auto sides = stratamesh::regionSidesFromCells(m);
        QCOMPARE(int(sides.size()), 2);
        // Bottom normals point down, out of "lower"; interface normals point up into "upper".
        QCOMPARE(sides[0], (std::vector<RegionSide>{{0, false}, {1, false}}));
        QCOMPARE(sides[1], (std::vector<RegionSide>{{1, true}}));
    }

    void validationNamesTheProblem()
    {
        VolumeMesh m = test::hybridMesh();
        validateMesh(m);
        m.cells[3].nodes[1] = 99;
        try {
            validateMesh(m);
            QFAIL("accepted a cell using a missing point");
        } catch (const InputError &e) {
            QVERIFY2(std::string(e.what()).find("pyramid 3 uses point 99") != std::string::npos,
                     e.what());
        }
        m = test::hybridMesh();
        m.triangleSurface[1] = 7;
        QVERIFY_THROWS_EXCEPTION(InputError, validateMesh(m));
        m = test::hybridMesh();
        m.cells[0].nodes[2] = m.cells[0].nodes[0];
        QVERIFY_THROWS_EXCEPTION(InputError, validateMesh(m));
        m = test::hybridMesh();
        m.points[0].x() = std::nan("");
        QVERIFY_THROWS_EXCEPTION(InputError, validateMesh(m));
    }

    void modelToMeshAndBack()
    {
        LayeredBoxParams p;
        p.fault = true;
        p.faultThrow = 40;
        p.edgeLength = 150;
        const Model model = recoverTopology(layeredBox(p));
        const VolumeMesh mesh = meshFromModel(model);
        validateMesh(mesh);
        // Conformal: shared surface vertices became one point each, as topology found them.
        QCOMPARE(mesh.points.size(), model.vertices.size());
        QCOMPARE(mesh.triangles.size(), model.triangleCount());
        QCOMPARE(mesh.lineNames.size(), model.lines.size());
        QCOMPARE(mesh.corners.size(), model.corners.size());
        QCOMPARE(mesh.regionNames.size(), model.regions.size());
        const Model back = modelFromMesh(mesh);
        const std::string diff = test::compareModels(model, back);
        QVERIFY2(diff.empty(), diff.c_str());
    }

    void cutSurfacesKeepTheirDuplicates()
    {
        // One surface with two vertices at the same place (a cut): they must stay two points.
        Model model;
        Surface s;
        s.name = "cut";
        s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
        s.triangles = {{0, 1, 2}, {3, 4, 2}};
        model.surfaces.push_back(s);
        Surface other;
        other.name = "other";
        other.vertices = {{1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
        other.triangles = {{0, 1, 2}};
        model.surfaces.push_back(other);
        const VolumeMesh mesh = meshFromModel(model);
        QCOMPARE(int(mesh.points.size()), 6); // 5 of "cut" + (2,0,0); (1,0,0) and (1,1,0) shared
        const Model back = modelFromMesh(mesh);
        QCOMPARE(int(back.surfaces[0].vertices.size()), 5);
        const std::string diff = test::compareModels(model, back);
        QVERIFY2(diff.empty(), diff.c_str());
    }

    void untaggedTrianglesBecomeASurface()
    {
        VolumeMesh m = test::hybridMesh();
        m.triangleSurface[0] = -1;
        const Model model = modelFromMesh(m);
        QCOMPARE(int(model.surfaces.size()), 3);
        QCOMPARE(model.surfaces.back().name, std::string("untagged"));
        QCOMPARE(int(model.surfaces.back().triangles.size()), 1);
    }
};

QTEST_GUILESS_MAIN(TestVolumeMesh)
#include "test_volume_mesh.moc"
