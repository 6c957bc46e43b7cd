// Gocad TSolid (.so): tet meshes with regions and surfaces read back identical, ZPOSITIVE Depth
// negates z both ways (tets negative in file coordinates, positive once read), ATOMs between
// TVOLUMEs share a point while ATOMs inside one TVOLUME make a crack, LightTSolid CTETRA regions.
#include "common/error.h"
#include "io/tsolid_reader.h"
#include "io/tsolid_writer.h"
#include "test_roundtrip_meshes.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

// Two unit cubes stacked, each cut into 6 tets around its main diagonal (Kuhn); regions "below"
// and "above"; surfaces "base" (z = 0) and "middle" (z = 1) with normals up.
VolumeMesh tetMesh()
{
    VolumeMesh m;
    m.name = "two cubes";
    for (int z = 0; z <= 2; ++z)
        for (int y = 0; y <= 1; ++y)
            for (int x = 0; x <= 1; ++x)
                m.points.push_back({x + 0.1 / 3.0, y * 1.0, z * 1.0});
    auto id = [](int x, int y, int z) { return x + 2 * y + 4 * z; };
    m.regionNames = {"below", "above"};
    for (int z = 0; z < 2; ++z) {
        // Kuhn paths from (0,0,0) to (1,1,1) through the three axes in every order.
        const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (const auto &perm : perms) {
            int p[3] = {0, 0, 0};
            int nodes[4];
            nodes[0] = id(0, 0, z);
            for (int k = 0; k < 3; ++k) {
                ++p[perm[k]];
                nodes[k + 1] = id(p[0], p[1], z + p[2]);
            }
            Cell c = Cell::tet(nodes[0], nodes[1], nodes[2], nodes[3]);
            if (signedVolume(m, c) < 0)
                std::swap(c.nodes[1], c.nodes[2]);
            m.cells.push_back(c);
            m.cellRegion.push_back(z);
        }
    }
    m.surfaces = {{"base", "box", FeatureType::Boundary},
                  {"middle_1", "middle", FeatureType::Horizon}};
    // Diagonal (0,0)-(1,1) as in the Kuhn split.
    for (int z = 0; z < 2; ++z) {
        m.triangles.push_back({id(0, 0, z), id(1, 0, z), id(1, 1, z)});
        m.triangles.push_back({id(0, 0, z), id(1, 1, z), id(0, 1, z)});
        m.triangleSurface.push_back(z);
        m.triangleSurface.push_back(z);
    }
    m.regionBoundaries = regionSidesFromCells(m);
    return m;
}

void writeFile(const QString &path, const QByteArray &text)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

test::MeshCompare tsolidCompare()
{
    test::MeshCompare c;
    c.lines = false;   // TSolid has no line or corner
    c.quality = false; // nor our cell data
    return c;
}

} // namespace

class TestTSolid : public QObject {
    Q_OBJECT

private slots:
    void roundTrip_data()
    {
        QTest::addColumn<bool>("depth");
        QTest::newRow("elevation") << false;
        QTest::newRow("depth") << true;
    }
    void roundTrip()
    {
        QFETCH(bool, depth);
        VolumeMesh m = tetMesh();
        m.zPositiveDepth = depth;
        QCOMPARE(m.regionBoundaries,
                 (std::vector<std::vector<RegionSide>>{{{0, true}, {1, false}}, {{1, true}}}));
        QTemporaryDir dir;
        const QString path = dir.filePath("cubes.so");
        writeGocadTSolid(m, path.toStdString());
        const VolumeMesh back = readGocadTSolid(path.toStdString());
        const std::string diff = test::compareMeshes(m, back, tsolidCompare());
        QVERIFY2(diff.empty(), diff.c_str());
        QCOMPARE(back.zPositiveDepth, depth);
        QCOMPARE(back.name, m.name);
        for (const Cell &c : back.cells)
            QVERIFY(signedVolume(back, c) > 0);
    }

    void depthNegatesZInTheFile()
    {
        VolumeMesh m = tetMesh();
        m.zPositiveDepth = true;
        QTemporaryDir dir;
        const QString path = dir.filePath("cubes.so");
        writeGocadTSolid(m, path.toStdString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.contains("ZPOSITIVE Depth"));
        QVERIFY(text.contains("VRTX 1 0.03333333333333333 0 -0\n"));
        QVERIFY(text.contains(" 1 -2\n")); // a top vertex, z = 2 written as -2
        QVERIFY(text.contains("TVOLUME below\n") && text.contains("TVOLUME above\n"));
        QVERIFY(text.contains("ATOM ")); // the shared middle layer in the second TVOLUME
        QVERIFY(text.contains("*tface*2*name: middle_1"));
        QVERIFY(text.contains("SURFACE middle\nTFACE 2\n"));
    }

    void prismsAreRefused()
    {
        QTemporaryDir dir;
        try {
            writeGocadTSolid(test::hybridMesh(), dir.filePath("h.so").toStdString());
            QFAIL("wrote prisms into a TSolid");
        } catch (const InputError &e) {
            QVERIFY2(std::string(e.what()).find("2 prisms and 5 pyramids") != std::string::npos,
                     e.what());
        }
        QVERIFY(!QFile::exists(dir.filePath("h.so")));
    }

    void atomsAndCracks()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("atoms.so");
        writeFile(path, "GOCAD TSolid 1\nHEADER {\nname:atoms\n}\n"
                        "TVOLUME A\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nVRTX 4 0 0 1\n"
                        "ATOM 5 4\n" // same TVOLUME: a crack, a new point at (0,0,1)
                        "TETRA 1 2 3 4\nTETRA 2 3 5 1\n"
                        "TVOLUME \"B side\"\nATOM 6 2\nATOM 7 3\nATOM 8 4\nVRTX 9 1 1 1\n"
                        "TETRA 6 9 7 8\n"
                        "MODEL\nSURFACE wall\nTFACE 1\nKEYVERTICES 2 3 4\nTRGL 2 3 4\nEND\n");
        const VolumeMesh m = readGocadTSolid(path.toStdString());
        QCOMPARE(int(m.points.size()), 6); // 4 + crack copy + (1,1,1); ATOMs 6-8 share points
        QCOMPARE(m.regionNames, (std::vector<std::string>{"A", "B side"}));
        QCOMPARE(m.cellRegion, (std::vector<int>{0, 0, 1}));
        QCOMPARE(m.cells[1].nodes[2], 4);                   // the crack copy
        QCOMPARE(m.cells[2].nodes[0], m.cells[0].nodes[1]); // ATOM 6 -> vertex 2
        QCOMPARE(m.name, std::string("atoms"));
        QCOMPARE(m.surfaces.front().name, std::string("wall"));
        // The wall separates A and B, on opposite sides: sides come from the cells.
        QCOMPARE(int(m.regionBoundaries.size()), 2);
        QCOMPARE(int(m.regionBoundaries[0].size() + m.regionBoundaries[1].size()), 2);
        QVERIFY(m.regionBoundaries[0][0].positive != m.regionBoundaries[1][0].positive);
    }

    void lightTSolidRegionsFromCtetra()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("light.so");
        writeFile(path,
                  "GOCAD LightTSolid 1\nVRTX 1 0 0 0 XYZ\nVRTX 2 1 0 0 XYZ\nVRTX 3 0 1 0 XYZ\n"
                  "VRTX 4 0 0 1 XYZ\nVRTX 5 1 1 1 XYZ\nSHAREDVRTX 6 2\n"
                  "TETRA 1 2 3 4\n# CTETRA north none none none none\n"
                  "TETRA 6 5 3 4\n# CTETRA \"south rock\" none none none none\nEND\n");
        const VolumeMesh m = readGocadTSolid(path.toStdString());
        QCOMPARE(m.regionNames, (std::vector<std::string>{"north", "south rock"}));
        QCOMPARE(m.cellRegion, (std::vector<int>{0, 1}));
        QCOMPARE(int(m.points.size()), 5);
    }

    void errorsNameTheLine_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("expected");
        QTest::newRow("not tsolid") << QByteArray("GOCAD TSurf 1\n") << "x.so:1: expected a TSolid";
        QTest::newRow("unknown vertex")
            << QByteArray("GOCAD TSolid 1\nTVOLUME a\nVRTX 1 0 0 0\nTETRA 1 2 3 4\n")
            << "x.so:4: vertex 2 is not defined";
        QTest::newRow("bad coordinate")
            << QByteArray("GOCAD TSolid 1\nTVOLUME a\nVRTX 1 0 north 0\n") << "x.so:3: expected y";
        QTest::newRow("bad atom") << QByteArray("GOCAD TSolid 1\nTVOLUME a\nATOM 3 1\n")
                                  << "x.so:3: ATOM 3 refers to vertex 1";
        QTest::newRow("duplicate id")
            << QByteArray("GOCAD TSolid 1\nTVOLUME a\nVRTX 1 0 0 0\nVRTX 1 1 0 0\n")
            << "x.so:4: vertex id 1 is used twice";
    }
    void errorsNameTheLine()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath("x.so");
        writeFile(path, text);
        try {
            readGocadTSolid(path.toStdString());
            QFAIL("accepted a bad file");
        } catch (const FileError &e) {
            QVERIFY2(std::string(e.what()).find(expected.toStdString()) != std::string::npos,
                     e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestTSolid)
#include "test_tsolid.moc"
