// Real models through every format: read -> write -> read keeps counts, exact coordinates, names
// and regions (modelA1, A2, A5 as surface models; the sample TSolids as tet meshes), and Debian's
// gmsh and python3-meshio accept the files with the same counts.
#include "io/gmsh_writer.h"
#include "io/gocad_writer.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/tsolid_writer.h"
#include "mesh/model_conversion.h"
#include "model/topology.h"
#include "support/test_data.h"
#include "test_roundtrip_meshes.h"

#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

struct Format {
    const char *extension;
    GmshWriteOptions::Version gmsh = GmshWriteOptions::Version::V41;
    bool featureMetadata = true; // feature names and types survive
    bool regionSides = true;
    bool quality = true;
};

const std::vector<Format> &meshFormats()
{
    static const std::vector<Format> formats = {
        {"msh", GmshWriteOptions::Version::V41, false, true, false},
        {"msh", GmshWriteOptions::Version::V22, false, false, false},
        {"vtu"},
        {"vtk"},
    };
    return formats;
}

QString label(const Format &f)
{
    return QString(f.extension)
           + (QString(f.extension) == "msh"
                  ? (f.gmsh == GmshWriteOptions::Version::V41 ? " 4.1" : " 2.2")
                  : QString());
}

} // namespace

class TestRoundTripRealModels : public QObject {
    Q_OBJECT

private slots:
    void surfaceModels_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("modelA1") << "modelA1.ml";
        QTest::newRow("modelA2") << "modelA2.ml";
        QTest::newRow("modelA5") << "modelA5.ml";
    }
    void surfaceModels()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        const Model model = recoverTopology(readModel(path.toStdString()));
        QTemporaryDir dir;

        // Gocad: everything survives, Universe included.
        const std::string ml = dir.filePath("m.ml").toStdString();
        writeGocadModel3d(model, ml);
        const Model backMl = readModel(ml);
        std::string diff = test::compareModels(model, backMl);
        QVERIFY2(diff.empty(), ("ml: " + diff).c_str());
        QCOMPARE(backMl.zPositiveDepth, model.zPositiveDepth);
        QCOMPARE(backMl.universe.size(), model.universe.size());
        const std::string ts = dir.filePath("m.ts").toStdString();
        writeGocadTSurf(model, ts);
        test::ModelCompare noRegions;
        noRegions.regions = false;
        diff = test::compareModels(model, readModel(ts), noRegions);
        QVERIFY2(diff.empty(), ("ts: " + diff).c_str());

        // Single-surface formats: the largest surface, exactly (STL: floats by definition).
        int largest = 0;
        for (int i = 0; i < int(model.surfaces.size()); ++i)
            if (model.surfaces[i].triangles.size() > model.surfaces[largest].triangles.size())
                largest = i;
        for (const char *ext : {"obj", "off", "ply"}) {
            const std::string out = dir.filePath(QString("s.") + ext).toStdString();
            ExportOptions options;
            options.surface = largest;
            exportModel(model, out, options);
            const Model back = QString(ext) == "ply" ? readMeshAsModel(out) : readModel(out);
            QCOMPARE(back.surfaces.size(), std::size_t(1));
            QCOMPARE(back.surfaces[0].vertices, model.surfaces[largest].vertices);
            QCOMPARE(back.surfaces[0].triangles, model.surfaces[largest].triangles);
        }

        // Meshes: the conformal surface mesh with its lines and corners.
        const VolumeMesh mesh = meshFromModel(model);
        std::vector<Format> formats = meshFormats();
        formats.push_back({"vtp"});
        for (const Format &f : formats) {
            const std::string out = dir.filePath(QString("m.") + f.extension).toStdString();
            ExportOptions options;
            options.gmsh.version = f.gmsh;
            exportModel(model, out, options);
            const VolumeMesh back = readVolumeMesh(out);
            test::MeshCompare c;
            c.surfaceMetadata = f.featureMetadata;
            c.regionSides = f.regionSides;
            c.quality = f.quality;
            diff = test::compareMeshes(mesh, back, c);
            QVERIFY2(diff.empty(), qPrintable(label(f) + ": " + QString::fromStdString(diff)));
            test::ModelCompare mc;
            mc.featureNames = mc.types = f.featureMetadata;
            mc.regions = f.regionSides;
            diff = test::compareModels(model, modelFromMesh(back), mc);
            QVERIFY2(diff.empty(),
                     qPrintable(label(f) + " as model: " + QString::fromStdString(diff)));
        }
    }

    void tetMeshes_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("cube_model_equi") << "cube_model_equi.so";
        QTest::newRow("solid_surf_inside") << "solid_surf_inside.so";
    }
    void tetMeshes()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        const VolumeMesh mesh = readVolumeMesh(path.toStdString());
        QVERIFY(mesh.zPositiveDepth);
        // formats.md fact 2: negative in file coordinates, positive once z-flipped.
        for (const Cell &c : mesh.cells)
            QVERIFY(signedVolume(mesh, c) > 0);
        QVERIFY(!mesh.surfaces.empty() && !mesh.triangles.empty());
        QTemporaryDir dir;
        std::vector<Format> formats = meshFormats();
        formats.push_back({"so"});
        for (const Format &f : formats) {
            const std::string out = dir.filePath(QString("m.") + f.extension).toStdString();
            ExportOptions options;
            options.gmsh.version = f.gmsh;
            exportVolumeMesh(mesh, out, options);
            const VolumeMesh back = readVolumeMesh(out);
            test::MeshCompare c;
            c.surfaceMetadata = f.featureMetadata && QString(f.extension) != "so";
            c.regionSides = QString(f.extension) != "msh";
            diff(mesh, back, c, label(f));
            if (QTest::currentTestFailed())
                return;
        }
    }

    void independentReaders()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA5.ml");
        const Model model = recoverTopology(readModel(path.toStdString()));
        const VolumeMesh mesh = meshFromModel(model);
        QTemporaryDir dir;
        const QString msh = dir.filePath("a5.msh"), vtu = dir.filePath("a5.vtu");
        exportModel(model, msh.toStdString());
        exportModel(model, vtu.toStdString());
        const QString gmsh = QStandardPaths::findExecutable("gmsh");
        if (gmsh.isEmpty()) {
            qWarning("*** gmsh is not installed: its check is SKIPPED ***");
        } else {
            QProcess p;
            p.start(gmsh, {msh, "-0", "-o", dir.filePath("out.msh"), "-format", "msh41"});
            QVERIFY(p.waitForFinished(120000));
            QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
            const VolumeMesh back = readVolumeMesh(dir.filePath("out.msh").toStdString());
            QCOMPARE(back.triangles.size(), mesh.triangles.size());
            QCOMPARE(back.edges.size(), mesh.edges.size());
            QCOMPARE(back.corners.size(), mesh.corners.size());
        }
        const QString python = test::pythonWithMeshio();
        if (python.isEmpty())
            QSKIP("*** python3-meshio is not installed: its check is SKIPPED ***");
        for (const QString &file : {msh, vtu}) {
            QProcess p;
            p.start(
                python,
                {"-c",
                 "import sys, meshio\n"
                 "m = meshio.read(sys.argv[1])\n"
                 "c = {}\n"
                 "for b in m.cells: c[b.type] = c.get(b.type, 0) + len(b.data)\n"
                 "print(len(m.points), c.get('triangle',0), c.get('line',0), c.get('vertex',0))\n",
                 file});
            QVERIFY(p.waitForFinished(120000));
            QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
            QCOMPARE(QString(p.readAllStandardOutput()).trimmed(), QString("%1 %2 %3 %4")
                                                                       .arg(mesh.points.size())
                                                                       .arg(mesh.triangles.size())
                                                                       .arg(mesh.edges.size())
                                                                       .arg(mesh.corners.size()));
        }
    }

private:
    void diff(const VolumeMesh &a, const VolumeMesh &b, const test::MeshCompare &c,
              const QString &what)
    {
        const std::string d = test::compareMeshes(a, b, c);
        QVERIFY2(d.empty(), qPrintable(what + ": " + QString::fromStdString(d)));
    }
};

QTEST_GUILESS_MAIN(TestRoundTripRealModels)
#include "test_roundtrip_real_models.moc"
