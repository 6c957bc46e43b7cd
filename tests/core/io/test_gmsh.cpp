// Gmsh MSH 4.1 and 2.2: our files read back identical (groups, names, exact coordinates, region
// sides of surface models), untagged elements follow Gmsh's rule, errors name the line, and the
// independent readers (Debian's gmsh, python3-meshio) accept our files with the same counts.
#include "common/error.h"
#include "io/gmsh_reader.h"
#include "io/gmsh_writer.h"
#include "mesh/model_conversion.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "test_roundtrip_meshes.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

using Version = GmshWriteOptions::Version;

VolumeMesh roundTrip(const VolumeMesh &m, const QString &path, GmshWriteOptions options = {})
{
    writeGmsh(m, path.toStdString(), options);
    return readGmsh(path.toStdString());
}

void writeFile(const QString &path, const QByteArray &text)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

std::string readError(const QString &path)
{
    try {
        readGmsh(path.toStdString());
    } catch (const FileError &e) {
        return e.what();
    }
    return {};
}

test::MeshCompare gmshCompare()
{
    test::MeshCompare c;
    c.surfaceMetadata = false; // MSH has no feature name or type
    c.quality = false;         // nor cell data in the mesh sections we write
    return c;
}

} // namespace

class TestGmsh : public QObject {
    Q_OBJECT

private slots:
    void hybridRoundTrip_data()
    {
        QTest::addColumn<int>("version");
        QTest::newRow("4.1") << int(Version::V41);
        QTest::newRow("2.2") << int(Version::V22);
    }
    void hybridRoundTrip()
    {
        QFETCH(int, version);
        QTemporaryDir dir;
        const VolumeMesh m = test::hybridMesh();
        GmshWriteOptions o;
        o.version = Version(version);
        const VolumeMesh back = roundTrip(m, dir.filePath("hybrid.msh"), o);
        test::MeshCompare c = gmshCompare();
        c.regionSides = false; // the cells carry them; checked below
        const std::string diff = test::compareMeshes(m, back, c);
        QVERIFY2(diff.empty(), diff.c_str());
        QCOMPARE(regionSidesFromCells(back), regionSidesFromCells(m));
        // Node order is Gmsh's: the prisms and pyramids are still positive.
        for (const Cell &cell : back.cells)
            QVERIFY(signedVolume(back, cell) > 0);
    }

    void fileHasNamedGroupsAndEntities()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("h.msh");
        writeGmsh(test::hybridMesh(), path.toStdString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.startsWith("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n"));
        for (const char *name : {"3 1 \"lower\"", "3 2 \"upper\"", "2 1 \"bottom\"",
                                 "2 2 \"interface\"", "1 1 \"contact\"", "0 1 \"corners\""})
            QVERIFY2(text.contains(name), name);
        QVERIFY(text.contains("$Entities\n4 1 2 2\n"));
        // 17 significant digits where needed: 1 + 1e-9/3 is not representable in fewer.
        QVERIFY(text.contains("1.0000000003333334"));
    }

    void surfaceModelKeepsRegionSides()
    {
        LayeredBoxParams p;
        p.fault = true;
        p.faultThrow = 30;
        p.edgeLength = 200;
        const Model model = recoverTopology(layeredBox(p));
        const VolumeMesh mesh = meshFromModel(model);
        QTemporaryDir dir;
        const VolumeMesh back = roundTrip(mesh, dir.filePath("model.msh"));
        const std::string diff = test::compareMeshes(mesh, back, gmshCompare());
        QVERIFY2(diff.empty(), diff.c_str());
        // The model comes back with its surfaces, regions and sides.
        test::ModelCompare mc;
        mc.featureNames = mc.types = false;
        const std::string modelDiff = test::compareModels(model, modelFromMesh(back), mc);
        QVERIFY2(modelDiff.empty(), modelDiff.c_str());
    }

    void untaggedElementsFollowGmsh()
    {
        VolumeMesh m = test::hybridMesh();
        m.cellRegion[8] = -1;
        m.triangleSurface[0] = -1;
        QTemporaryDir dir;
        const QString path = dir.filePath("u.msh");
        const GmshWriteResult skipped = writeGmsh(m, path.toStdString());
        QCOMPARE(int(skipped.untaggedSkipped), 2);
        VolumeMesh back = readGmsh(path.toStdString());
        QCOMPARE(int(back.cells.size()), 8);
        QCOMPARE(int(back.triangles.size()), 3);
        QCOMPARE(back.points.size(), m.points.size()); // nodes are kept even when unused
        for (Version v : {Version::V41, Version::V22}) {
            GmshWriteOptions all;
            all.saveAll = true;
            all.version = v;
            const GmshWriteResult kept = writeGmsh(m, path.toStdString(), all);
            QCOMPARE(int(kept.untaggedSkipped), 0);
            back = readGmsh(path.toStdString());
            const std::string diff = test::compareMeshes(m, back, gmshCompare());
            QVERIFY2(diff.empty(), diff.c_str()); // untagged read back as untagged (-1)
        }
    }

    void foreignFilesWithoutGroups()
    {
        // No physical groups: each elementary entity is a group.
        QTemporaryDir dir;
        const QString path = dir.filePath("plain.msh");
        writeFile(
            path,
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
            "4 0 0 1\n7 1 1 1\n$EndNodes\n$Elements\n3\n1 4 2 0 5 1 2 3 4\n2 4 2 0 6 2 3 4 7\n"
            "3 2 2 0 9 1 3 2\n$EndElements\n");
        const VolumeMesh m = readGmsh(path.toStdString());
        QCOMPARE(m.regionNames, (std::vector<std::string>{"region_5", "region_6"}));
        QCOMPARE(m.cellRegion, (std::vector<int>{0, 1}));
        QCOMPARE(int(m.surfaces.size()), 1);
        QCOMPARE(m.cells[1].nodes[3], 4); // node tag 7 is the fifth node
    }

    void errorsNameTheLine_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("expected");
        const QByteArray head =
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
            "4 0 0 1\n$EndNodes\n";
        QTest::newRow("binary") << QByteArray("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n")
                                << "x.msh:2: binary";
        QTest::newRow("version") << QByteArray("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n")
                                 << "x.msh:2: MSH version 3.0";
        QTest::newRow("hexahedron")
            << head + "$Elements\n1\n1 5 2 0 1 1 2 3 4 1 2 3 4\n$EndElements\n"
            << "x.msh:13: element type 5 (hexahedron) is not supported";
        QTest::newRow("unknown node") << head + "$Elements\n1\n1 4 2 0 1 1 2 3 9\n$EndElements\n"
                                      << "x.msh:13: element uses node 9";
        QTest::newRow("bad number")
            << QByteArray("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 zero 0\n")
            << "x.msh:6: expected y";
        QTest::newRow("truncated") << head + "$Elements\n2\n1 4 2 0 1 1 2 3 4\n"
                                   << "x.msh:14: unexpected end of file";
        QTest::newRow("not gmsh") << QByteArray("hello\n") << "x.msh:1: unexpected text";
    }
    void errorsNameTheLine()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath("x.msh");
        writeFile(path, text);
        const std::string error = readError(path);
        QVERIFY2(error.find(expected.toStdString()) != std::string::npos, error.c_str());
    }

    // Debian's gmsh loads each file and saves it again with the same element counts.
    void gmshAcceptsOurFiles_data()
    {
        QTest::addColumn<int>("version");
        QTest::addColumn<bool>("saveAll");
        QTest::newRow("4.1") << int(Version::V41) << false;
        QTest::newRow("2.2") << int(Version::V22) << false;
        QTest::newRow("4.1 save all") << int(Version::V41) << true;
        QTest::newRow("2.2 save all") << int(Version::V22) << true;
    }
    void gmshAcceptsOurFiles()
    {
        QFETCH(int, version);
        QFETCH(bool, saveAll);
        const QString gmsh = QStandardPaths::findExecutable("gmsh");
        if (gmsh.isEmpty())
            QSKIP("*** gmsh is not installed (apt-get install gmsh): independent reader check "
                  "SKIPPED ***");
        QTemporaryDir dir;
        VolumeMesh m = test::hybridMesh();
        if (saveAll)
            m.cellRegion[8] = -1;
        GmshWriteOptions o;
        o.version = Version(version);
        o.saveAll = saveAll;
        const QString in = dir.filePath("in.msh"), out = dir.filePath("out.msh");
        writeGmsh(m, in.toStdString(), o);
        QStringList args{in,  "-0",      "-o",
                         out, "-format", version == int(Version::V41) ? "msh41" : "msh22"};
        if (saveAll)
            args << "-save_all";
        QProcess p;
        p.start(gmsh, args);
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0,
                 p.readAllStandardError().constData());
        const VolumeMesh back = readGmsh(out.toStdString());
        for (CellType t : {CellType::Tet, CellType::Pyramid, CellType::Prism})
            QCOMPARE(back.countCells(t), m.countCells(t));
        QCOMPARE(back.triangles.size(), m.triangles.size());
        QCOMPARE(back.edges.size(), m.edges.size());
        QCOMPARE(back.corners.size(), m.corners.size());
        // Gmsh prints 16 significant digits, so its copy is compared by groups, not bit by bit.
        QCOMPARE(back.regionNames, m.regionNames);
        QCOMPARE(back.lineNames, m.lineNames);
        QCOMPARE(back.surfaces.size(), m.surfaces.size());
        for (std::size_t s = 0; s < m.surfaces.size(); ++s)
            QCOMPARE(back.surfaces[s].name, m.surfaces[s].name);
        if (!saveAll) { // Gmsh may reorder elements (MSH 2.2: by type)
            std::vector<int> a = back.cellRegion, b = m.cellRegion;
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            QCOMPARE(a, b);
        }
        for (const Cell &cell : back.cells)
            QVERIFY(signedVolume(back, cell) > 0);
    }

    void meshioReadsOurFiles_data()
    {
        QTest::addColumn<int>("version");
        QTest::newRow("4.1") << int(Version::V41);
        QTest::newRow("2.2") << int(Version::V22);
    }
    void meshioReadsOurFiles()
    {
        QFETCH(int, version);
        const QString python = test::pythonWithMeshio();
        if (python.isEmpty())
            QSKIP("*** python3-meshio is not installed: independent reader check SKIPPED ***");
        QTemporaryDir dir;
        const QString path = dir.filePath("m.msh");
        GmshWriteOptions o;
        o.version = Version(version);
        writeGmsh(test::hybridMesh(), path.toStdString(), o);
        QProcess p;
        p.start(python,
                {"-c",
                 "import sys, meshio\n"
                 "m = meshio.read(sys.argv[1])\n"
                 "c = {}\n"
                 "for b in m.cells: c[b.type] = c.get(b.type, 0) + len(b.data)\n"
                 "print(len(m.points), c.get('tetra',0), c.get('pyramid',0), c.get('wedge',0),"
                 " c.get('triangle',0), c.get('line',0), c.get('vertex',0))\n",
                 path});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(QString(p.readAllStandardOutput()).trimmed(), QStringLiteral("13 2 5 2 4 4 4"));
    }
};

QTEST_GUILESS_MAIN(TestGmsh)
#include "test_gmsh.moc"
