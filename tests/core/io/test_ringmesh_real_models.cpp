// RINGMesh GeoModels of ../shared/data: the three format versions of modelA1 against modelA1.ml,
// the tets of the volume-meshed models against their B-Rep volumes, round trips through .gm of
// modelA1, A2 and A5, and the layout of our archive against the one RINGMesh wrote for modelA1.
#include "io/geogram_file.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/ringmesh_reader.h"
#include "io/ringmesh_topology.h"
#include "io/ringmesh_writer.h"
#include "io/zip_archive.h"
#include "model/model_counts.h"
#include "model/region_volume.h"
#include "model/topology.h"
#include "support/test_data.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <map>
#include <set>
#include <sstream>

using namespace stratamesh;

namespace {

bool sameBits(const Vec3 &a, const Vec3 &b)
{
    return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

// Everything a round trip must keep, compared exactly.
void compareModels(const Model &a, const Model &b)
{
    QCOMPARE(b.surfaces.size(), a.surfaces.size());
    for (std::size_t s = 0; s < a.surfaces.size(); ++s) {
        const Surface &x = a.surfaces[s], &y = b.surfaces[s];
        QCOMPARE(y.name, x.name);
        QCOMPARE(y.featureName, x.featureName);
        QCOMPARE(int(y.type), int(x.type));
        QCOMPARE(y.triangles, x.triangles);
        QCOMPARE(y.vertices.size(), x.vertices.size());
        for (std::size_t v = 0; v < x.vertices.size(); ++v)
            QVERIFY2(sameBits(x.vertices[v], y.vertices[v]),
                     qPrintable(QString("surface %1 vertex %2 moved").arg(s).arg(v)));
    }
    QCOMPARE(b.regions.size(), a.regions.size());
    for (std::size_t r = 0; r < a.regions.size(); ++r) {
        QCOMPARE(b.regions[r].name, a.regions[r].name);
        QVERIFY(b.regions[r].boundaries == a.regions[r].boundaries);
    }
    QCOMPARE(b.layers.size(), a.layers.size());
    for (std::size_t l = 0; l < a.layers.size(); ++l) {
        QCOMPARE(b.layers[l].name, a.layers[l].name);
        QCOMPARE(b.layers[l].regions, a.layers[l].regions);
    }
}

std::map<std::string, double> volumesByName(const Model &m)
{
    std::map<std::string, double> out;
    const std::vector<double> v = regionVolumes(m);
    for (std::size_t r = 0; r < m.regions.size(); ++r)
        out[m.regions[r].name] = v[r];
    return out;
}

// The "Type id name meshtype" lines of mesh_entities.txt without the names, which RINGMesh leaves
// as No_name, and the region side lines.
std::vector<std::string> entityStructure(const std::string &text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream f(line);
        std::string type, id, name, mesh;
        f >> type >> id >> name >> mesh;
        if (type == "Corner" || type == "Line" || type == "Surface" || type == "Region")
            out.push_back(type + " " + id + " " + mesh);
        else if (type == "Nb")
            out.push_back(line);
    }
    return out;
}

} // namespace

class TestRingMeshRealModels : public QObject {
    Q_OBJECT

private slots:
    void versionsMatchGocad_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("version 0") << "modelA1_version0.gm";
        QTest::newRow("version 1") << "modelA1_version1.gm";
        QTest::newRow("version 2") << "modelA1_version2.gm";
    }

    void versionsMatchGocad()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(gmPath, file);
        STRATAMESH_REQUIRE_DATA(mlPath, "modelA1.ml");
        QElapsedTimer timer;
        timer.start();
        const Model gm = recoverTopology(readModel(gmPath.toStdString()));
        qInfo("%s read in %lld ms", qPrintable(file), qint64(timer.elapsed()));
        const Model ml = recoverTopology(readModel(mlPath.toStdString()));

        const ModelCounts counts = countEntities(gm);
        QCOMPARE(counts.withoutBox.regions, 4); // thesis Table 3.1
        QCOMPARE(counts.withoutBox.surfaces, 3);
        QCOMPARE(counts.withoutBox.lines, 0);
        QCOMPARE(counts.withoutBox.corners, 0);
        QVERIFY(counts.all == countEntities(ml).all);
        QCOMPARE(counts.all.lines, 36); // as mesh_entities.txt lists them
        QCOMPARE(counts.all.corners, 20);
        QCOMPARE(gm.triangleCount(), ml.triangleCount());

        const std::map<std::string, double> gv = volumesByName(gm), mv = volumesByName(ml);
        QCOMPARE(gv.size(), std::size_t(4));
        for (const auto &[name, volume] : mv) {
            QVERIFY2(gv.count(name), name.c_str());
            QVERIFY(volume > 0);
            QVERIFY2(
                std::abs(gv.at(name) - volume) <= 1e-9 * volume,
                qPrintable(QString("%1: %2 vs %3").arg(name.c_str()).arg(gv.at(name)).arg(volume)));
        }

        // RINGMesh names the horizon interfaces after the Gocad TSURFs (modelA1.ml gives all three
        // GEOLOGICAL_FEATURE h1_model1, so compare with their source objects).
        std::set<std::string> gmHorizons, mlHorizons;
        for (const Surface &s : gm.surfaces)
            if (s.type == FeatureType::Horizon)
                gmHorizons.insert(s.featureName);
        for (const Surface &s : ml.surfaces)
            if (s.type == FeatureType::Horizon)
                mlHorizons.insert(s.sourceObject);
        QCOMPARE(gmHorizons, (std::set<std::string>{"h1_model1", "h2_model1", "h3_model1"}));
        QCOMPARE(gmHorizons, mlHorizons);

        // Same surfaces in the same order, with the Gocad patch names and the z-up coordinates.
        QCOMPARE(gm.surfaces.size(), ml.surfaces.size());
        for (std::size_t s = 0; s < ml.surfaces.size(); ++s) {
            QCOMPARE(gm.surfaces[s].name, ml.surfaces[s].name);
            QCOMPARE(int(gm.surfaces[s].type), int(ml.surfaces[s].type));
            QCOMPARE(gm.surfaces[s].triangles.size(), ml.surfaces[s].triangles.size());
        }
    }

    void volumeMeshes_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("regions");
        QTest::newRow("modelA1") << "modelA1_volume_meshed.gm" << 4;
        QTest::newRow("unit cube") << "unit_cube_volume_meshed.gm" << 1;
    }

    void volumeMeshes()
    {
        QFETCH(QString, file);
        QFETCH(int, regions);
        STRATAMESH_REQUIRE_DATA(path, file);
        QElapsedTimer timer;
        timer.start();
        const VolumeMesh mesh = readVolumeMesh(path.toStdString());
        qInfo("%s: %zu points, %zu tets, read in %lld ms", qPrintable(file), mesh.points.size(),
              mesh.cells.size(), qint64(timer.elapsed()));
        validateMesh(mesh);
        const Model model = readModel(path.toStdString());
        const std::vector<double> brep = regionVolumes(model);
        QCOMPARE(int(brep.size()), regions);
        QCOMPARE(int(mesh.regionNames.size()), regions);
        std::vector<double> sum(regions, 0.0);
        std::vector<int> tets(regions, 0);
        for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
            QCOMPARE(int(mesh.cells[c].type), int(CellType::Tet));
            const double v = signedVolume(mesh, mesh.cells[c]);
            QVERIFY2(v > 0, qPrintable(QString("tet %1 has volume %2").arg(c).arg(v)));
            const int r = mesh.cellRegion[c];
            QVERIFY(r >= 0 && r < regions);
            sum[r] += v;
            ++tets[r];
        }
        for (int r = 0; r < regions; ++r) {
            QVERIFY(tets[r] > 0);
            qInfo("region %s: %d tets, volume %.10g, B-Rep %.10g, relative difference %.3g",
                  model.regions[r].name.c_str(), tets[r], sum[r], brep[r],
                  (sum[r] - brep[r]) / brep[r]);
            QVERIFY(brep[r] > 0);
            QVERIFY(std::abs(sum[r] - brep[r]) <= 1e-6 * brep[r]);
        }
        if (regions == 1)
            QVERIFY(std::abs(sum[0] - 1.0) < 1e-12); // the unit cube
    }

    void volumeMeshRoundTrip()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1_volume_meshed.gm");
        QTemporaryDir dir;
        const VolumeMesh a = readVolumeMesh(path.toStdString());
        const std::string out = dir.filePath("tets.gm").toStdString();
        exportVolumeMesh(a, out);
        const VolumeMesh b = readVolumeMesh(out);
        QCOMPARE(b.cells.size(), a.cells.size());
        QCOMPARE(b.cellRegion, a.cellRegion);
        QCOMPARE(b.points.size(), a.points.size());
        for (std::size_t c = 0; c < a.cells.size(); ++c)
            for (int k = 0; k < 4; ++k)
                QVERIFY(sameBits(a.points[a.cells[c].nodes[k]], b.points[b.cells[c].nodes[k]]));
    }

    void roundTrip_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("modelA1.gm") << "modelA1_version2.gm";
        QTest::newRow("modelA1.ml") << "modelA1.ml";
        QTest::newRow("modelA2.ml") << "modelA2.ml";
        QTest::newRow("modelA5.ml") << "modelA5.ml";
    }

    // source → .gm → model → .gm → model: the two models read from .gm are identical, and equal to
    // the source in all the .gm stores.
    void roundTrip()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        QTemporaryDir dir;
        const Model source = recoverTopology(readModel(path.toStdString()));
        const std::string first = dir.filePath("first.gm").toStdString();
        const std::string second = dir.filePath("second.gm").toStdString();
        QElapsedTimer timer;
        timer.start();
        const ExportReport report = exportModel(source, first);
        qInfo("%s written in %lld ms", qPrintable(file), qint64(timer.elapsed()));
        QCOMPARE(report.format, std::string("RINGMesh GeoModel"));
        const Model a = recoverTopology(readModel(first));
        writeRingMeshModel(a, second);
        const Model b = recoverTopology(readModel(second));
        compareModels(a, b);
        compareModels(source, a);
        QVERIFY(countEntities(a).all == countEntities(source).all);
        QVERIFY(countEntities(b).withoutBox == countEntities(source).withoutBox);
        QCOMPARE(a.name, source.name);
        if (!source.universe.empty())
            QVERIFY(a.universe == source.universe);
    }

    // Our archive of modelA1 has RINGMesh's layout: the same entries in the same order, the same
    // entity lines and counts, and Surface GeoFiles with the same attribute sets and sizes.
    void layoutMatchesRingMesh()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1_version2.gm");
        QTemporaryDir dir;
        const std::string out = dir.filePath("modelA1.gm").toStdString();
        writeRingMeshModel(recoverTopology(readModel(path.toStdString())), out);
        const ZipReader theirs(path.toStdString()), ours(out);
        QCOMPARE(ours.names(), theirs.names());
        QCOMPARE(entityStructure(ours.read("mesh_entities.txt")),
                 entityStructure(theirs.read("mesh_entities.txt")));
        for (const std::string &name : theirs.names()) {
            if (name.rfind("Surface_", 0) != 0)
                continue;
            const GeogramFile a = readGeogramFile(theirs.read(name), name);
            const GeogramFile b = readGeogramFile(ours.read(name), name);
            for (const char *set :
                 {"GEO::Mesh::vertices", "GEO::Mesh::facets", "GEO::Mesh::facet_corners"}) {
                QVERIFY(a.findSet(set) && b.findSet(set));
                QCOMPARE(b.findSet(set)->items, a.findSet(set)->items);
            }
            for (const char *attr : {"GEO::Mesh::facet_corners::corner_vertex",
                                     "GEO::Mesh::facet_corners::corner_adjacent_facet"}) {
                const GeogramAttribute *x = a.find("GEO::Mesh::facet_corners", attr);
                const GeogramAttribute *y = b.find("GEO::Mesh::facet_corners", attr);
                QVERIFY(x && y);
                QCOMPARE(y->data, x->data); // same triangles, same adjacency as Geogram computed
            }
            QCOMPARE(b.find("GEO::Mesh::vertices", "point")->data,
                     a.find("GEO::Mesh::vertices", "point")->data);
        }
    }

    void fileTopologyAgrees_data()
    {
        QTest::addColumn<QString>("file");
        for (const char *f :
             {"modelA1_version0.gm", "modelA1_version1.gm", "modelA1_version2.gm",
              "modelA1_volume_meshed.gm", "unit_cube_volume_meshed.gm", "modelA2.ml", "modelA5.ml"})
            QTest::newRow(f) << f;
    }

    // RINGMesh's corners and lines are the ones we recover, on its files and on ours.
    void fileTopologyAgrees()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        QTemporaryDir dir;
        std::string gm = path.toStdString();
        if (!isRingMeshFile(gm)) {
            gm = dir.filePath("written.gm").toStdString();
            writeRingMeshModel(readModel(path.toStdString()), gm);
        }
        const Model model = recoverTopology(readModel(gm));
        const std::vector<ValidityProblem> problems = compareRingMeshTopology(gm, model);
        for (const ValidityProblem &p : problems)
            qWarning("%s", p.message.c_str());
        QVERIFY(problems.empty());
    }

    // A surface that forgets one of its boundary lines in mesh_entities.txt is named.
    void fileTopologyMismatchIsNamed()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1_version2.gm");
        QTemporaryDir dir;
        const std::string damaged = dir.filePath("damaged.gm").toStdString();
        {
            const ZipReader in(path.toStdString());
            ZipWriter out(damaged);
            for (const std::string &name : in.names()) {
                std::string bytes = in.read(name);
                if (name == "mesh_entities.txt") {
                    const std::string from =
                        "Surface 0 No_name GeogramSurfaceMesh\nboundary 0 1 2 7 \n";
                    const std::size_t at = bytes.find(from);
                    QVERIFY(at != std::string::npos);
                    bytes.replace(at, from.size(),
                                  "Surface 0 No_name GeogramSurfaceMesh\nboundary 0 1 2 \n");
                }
                out.add(name, bytes);
            }
            out.close();
        }
        const Model model = recoverTopology(readModel(damaged));
        const std::vector<ValidityProblem> problems = compareRingMeshTopology(damaged, model);
        QCOMPARE(problems.size(), std::size_t(1));
        qInfo("%s", problems[0].message.c_str());
        QCOMPARE(problems[0].check, std::string(kFileTopologyCheck));
        QCOMPARE(problems[0].entities,
                 (std::vector<std::string>{"h1_model1", "Front_1", "Front_2"}));
        QVERIFY(problems[0].message.rfind("Line 7 (", 0) == 0);
        QVERIFY(problems[0].message.find(
                    "the file gives it the surfaces {8, 9}, the recovered topology {0, 8, 9}")
                != std::string::npos);
        ValidityReport report;
        addRingMeshTopologyProblems(damaged, model, report);
        QVERIFY(!report.valid);
        QCOMPARE(report.count(kFileTopologyCheck), std::size_t(1));
    }

    void convertCommandPath()
    {
        // .gm dispatch in both readers: the model reader and the mesh reader agree on surfaces.
        STRATAMESH_REQUIRE_DATA(path, "modelA1_version1.gm");
        QVERIFY(isReadableModelFile(path.toStdString()));
        QVERIFY(isMeshReaderFile(path.toStdString()));
        QVERIFY(isExportFile("x.GM"));
        QVERIFY(!hasRingMeshRegionMeshes(path.toStdString()));
        const VolumeMesh mesh = readVolumeMesh(path.toStdString());
        QCOMPARE(mesh.triangles.size(), readModel(path.toStdString()).triangleCount());
        QVERIFY(!mesh.hasCells());
    }
};

QTEST_GUILESS_MAIN(TestRingMeshRealModels)
#include "test_ringmesh_real_models.moc"
