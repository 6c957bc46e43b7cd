// RINGMesh .gm output on models built in code: a faulted layered box (box, horizons, fault,
// layers), nested spheres (no line, no corner), a lone square (its border is a closed line, which
// RINGMesh needs cut at a corner) and a volume mesh of a prism and a pyramid (geogram cell types).
#include "common/error.h"
#include "io/geogram_file.h"
#include "io/ringmesh_reader.h"
#include "io/ringmesh_writer.h"
#include "io/zip_archive.h"
#include "model/model_counts.h"
#include "model/region_volume.h"
#include "model/synthetic_models.h"
#include "model/topology.h"

#include <QTemporaryDir>
#include <QtTest>

#include <map>
#include <sstream>

using namespace stratamesh;

namespace {

void compareSurfaceModels(const Model &a, const Model &b)
{
    QCOMPARE(b.surfaces.size(), a.surfaces.size());
    for (std::size_t s = 0; s < a.surfaces.size(); ++s) {
        QCOMPARE(b.surfaces[s].name, a.surfaces[s].name);
        QCOMPARE(b.surfaces[s].featureName, a.surfaces[s].featureName);
        QCOMPARE(int(b.surfaces[s].type), int(a.surfaces[s].type));
        QCOMPARE(b.surfaces[s].triangles, a.surfaces[s].triangles);
        QVERIFY(b.surfaces[s].vertices == a.surfaces[s].vertices);
    }
    QCOMPARE(b.regions.size(), a.regions.size());
    for (std::size_t r = 0; r < a.regions.size(); ++r) {
        QCOMPARE(b.regions[r].name, a.regions[r].name);
        QVERIFY(b.regions[r].boundaries == a.regions[r].boundaries);
    }
}

// The line of mesh_entities.txt right after the one starting with `key`.
std::string lineAfter(const std::string &text, const std::string &key)
{
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key, 0) == 0 && std::getline(in, line))
            return line;
    return "(absent)";
}

} // namespace

class TestRingMeshWriter : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    std::string file(const char *name) const { return m_dir.filePath(name).toStdString(); }

private slots:
    void faultedLayeredBox()
    {
        LayeredBoxParams p;
        p.fault = true;
        p.faultDipDegrees = 60;
        p.faultThrow = 50;
        p.edgeLength = 150;
        const Model model = recoverTopology(layeredBox(p));
        writeRingMeshModel(model, file("box.gm"));
        const Model back = recoverTopology(readRingMeshModel(file("box.gm")));
        compareSurfaceModels(model, back);
        QVERIFY(countEntities(back).all == countEntities(model).all);
        QVERIFY(countEntities(back).withoutBox == countEntities(model).withoutBox);
        QCOMPARE(back.layers.size(), model.layers.size());
        for (std::size_t l = 0; l < model.layers.size(); ++l) {
            QCOMPARE(back.layers[l].name, model.layers[l].name);
            QCOMPARE(back.layers[l].regions, model.layers[l].regions);
        }
        bool fault = false;
        for (const Surface &s : back.surfaces)
            fault = fault || (s.type == FeatureType::Fault && s.featureName == "F1");
        QVERIFY(fault);
        const std::vector<double> va = regionVolumes(model), vb = regionVolumes(back);
        for (std::size_t r = 0; r < va.size(); ++r)
            QCOMPARE(vb[r], va[r]);

        // The geological entities say what RINGMesh expects: "fault", "top", "boundary".
        const ZipReader zip(file("box.gm"));
        const std::string geology = zip.read("geological_entities.txt");
        QVERIFY(geology.find(" F1 fault\n") != std::string::npos);
        QVERIFY(geology.find(" H1 top\n") != std::string::npos);
        QVERIFY(geology.find(" box boundary\n") != std::string::npos);
        QVERIFY(geology.find("Nb Layer ") != std::string::npos);
        QCOMPARE(zip.names().at(0), std::string("mesh_entities.txt"));
        QCOMPARE(zip.names().at(1), std::string("geological_entities.txt"));
    }

    void nestedSpheresWithoutLines()
    {
        const Model model = recoverTopology(nestedSpheres({}));
        QVERIFY(model.lines.empty());
        writeRingMeshModel(model, file("spheres.gm"));
        const Model back = readRingMeshModel(file("spheres.gm"));
        compareSurfaceModels(model, back);
        QVERIFY(back.universe == model.universe);
    }

    void closedLineGetsACorner()
    {
        Model square;
        square.name = "square";
        Surface s;
        s.name = "sq";
        s.featureName = "sq";
        s.type = FeatureType::Horizon;
        s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        s.triangles = {{0, 1, 2}, {0, 2, 3}};
        square.surfaces.push_back(s);
        const Model topo = recoverTopology(square);
        QCOMPARE(topo.lines.size(), std::size_t(1));
        QVERIFY(topo.lines[0].closed);
        QVERIFY(topo.corners.empty());

        writeRingMeshModel(square, file("square.gm"));
        const ZipReader zip(file("square.gm"));
        const std::string entities = zip.read("mesh_entities.txt");
        QVERIFY(entities.find("Nb Corner 1\n") != std::string::npos);
        QCOMPARE(lineAfter(entities, "Line 0 "), std::string("boundary 0 0 "));
        QCOMPARE(lineAfter(entities, "Surface 0 "), std::string("boundary 0 "));
        // The loop is closed on the corner: 5 vertices, 4 edges, first and last at (0, 0, 0).
        const GeogramFile line = readGeogramFile(zip.read("Line_0.geogram"), "Line_0.geogram");
        QCOMPARE(line.findSet("GEO::Mesh::vertices")->items, 5u);
        QCOMPARE(line.findSet("GEO::Mesh::edges")->items, 4u);
        const std::vector<double> xyz =
            geogramDoubles(*line.find("GEO::Mesh::vertices", "point"), "");
        const GeogramFile corner =
            readGeogramFile(zip.read("Corner_0.geogram"), "Corner_0.geogram");
        const std::vector<double> c =
            geogramDoubles(*corner.find("GEO::Mesh::vertices", "point"), "");
        QCOMPARE(std::vector<double>(xyz.begin(), xyz.begin() + 3), c);
        QCOMPARE(std::vector<double>(xyz.end() - 3, xyz.end()), c);
        compareSurfaceModels(square, readRingMeshModel(file("square.gm")));
    }

    // A square cut along its diagonal (duplicated vertices) lies on both sides of the diagonal
    // line: RINGMesh lists such an internal border twice among the surface's boundaries.
    void internalBorderListedTwice()
    {
        Model model;
        model.name = "cut";
        Surface s;
        s.name = "cut";
        s.featureName = "cut";
        s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        s.triangles = {{0, 1, 2}, {3, 4, 5}};
        model.surfaces.push_back(s);
        const Model topo = recoverTopology(model);
        QCOMPARE(topo.lines.size(), std::size_t(3));
        int diagonal = -1;
        for (std::size_t l = 0; l < topo.lines.size(); ++l)
            if (topo.lines[l].vertices.size() == 2)
                diagonal = int(l);
        QVERIFY(diagonal >= 0);
        writeRingMeshModel(topo, file("cut.gm"));
        const ZipReader zip(file("cut.gm"));
        std::istringstream boundary(lineAfter(zip.read("mesh_entities.txt"), "Surface 0 "));
        std::string word;
        boundary >> word;
        QCOMPARE(word, std::string("boundary"));
        std::map<int, int> times;
        for (int l; boundary >> l;)
            ++times[l];
        QCOMPARE(times.size(), std::size_t(3));
        for (const auto &[line, count] : times)
            QCOMPARE(count, line == diagonal ? 2 : 1);
        const Model back = recoverTopology(readRingMeshModel(file("cut.gm")));
        compareSurfaceModels(topo, back);
    }

    void prismAndPyramid()
    {
        VolumeMesh mesh;
        mesh.name = "cells";
        // A unit prism (triangle 0-1-2 at z = 0 under 3-4-5) and a pyramid on the square x = 2..3.
        mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},    {0, 1, 1},
                       {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}, {2.5, 0.5, 1}};
        mesh.cells = {Cell::prism(0, 1, 2, 3, 4, 5), Cell::pyramid(6, 7, 8, 9, 10)};
        mesh.cellRegion = {0, 1};
        mesh.regionNames = {"prism", "pyramid"};
        mesh.surfaces = {{"skin", "skin", FeatureType::Boundary}};
        for (const Cell &c : mesh.cells)
            for (const Triangle &t : outwardTriangleFaces(c)) {
                mesh.triangles.push_back(t);
                mesh.triangleSurface.push_back(0);
            }
        QVERIFY(signedVolume(mesh, mesh.cells[0]) > 0);
        QVERIFY(signedVolume(mesh, mesh.cells[1]) > 0);
        writeRingMeshVolume(mesh, file("cells.gm"));
        const ZipReader zip(file("cells.gm"));
        const GeogramFile region1 =
            readGeogramFile(zip.read("Region_1.geogram"), "Region_1.geogram");
        QVERIFY(region1.find("GEO::Mesh::cells", "GEO::Mesh::cells::cell_type"));
        QCOMPARE(region1.find("GEO::Mesh::cells", "GEO::Mesh::cells::cell_type")->data,
                 std::string(1, '\3'));

        const VolumeMesh back = readRingMeshVolume(file("cells.gm"));
        QCOMPARE(back.cells.size(), std::size_t(2));
        QCOMPARE(back.cellRegion, mesh.cellRegion);
        for (std::size_t c = 0; c < 2; ++c) {
            QCOMPARE(int(back.cells[c].type), int(mesh.cells[c].type));
            for (int k = 0; k < mesh.cells[c].size(); ++k)
                QVERIFY(back.points[back.cells[c].nodes[k]] == mesh.points[mesh.cells[c].nodes[k]]);
            QCOMPARE(signedVolume(back, back.cells[c]), signedVolume(mesh, mesh.cells[c]));
        }
    }

    void emptyModelIsRefused()
    {
        Model empty;
        QVERIFY_THROWS_EXCEPTION(InputError, writeRingMeshModel(empty, file("empty.gm")));
        QVERIFY(!QFileInfo::exists(QString::fromStdString(file("empty.gm"))));
    }
};

QTEST_GUILESS_MAIN(TestRingMeshWriter)
#include "test_ringmesh_writer.moc"
