// VTK .vtu, legacy .vtk 4.2 and .vtp: our files read back identical (groups, names, types, region
// sides, quality, exact doubles); legacy files VTK's own writers make (unstructured grid and poly
// data, versions 4.2 and 5.1, ASCII and binary) read as the mesh they were made from; VTK itself
// finds a positive volume for every tet, pyramid and wedge we write; python3-meshio reads them
// with the same counts.
#include "common/error.h"
#include "io/vtk_reader.h"
#include "io/vtk_writer.h"
#include "mesh/model_conversion.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "test_roundtrip_meshes.h"

#include <vtkCellData.h>
#include <vtkCellSizeFilter.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSetReader.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

QString extensionOf(VtkFileKind kind)
{
    return kind == VtkFileKind::Vtu ? "vtu" : kind == VtkFileKind::LegacyVtk ? "vtk" : "vtp";
}

// Signed volumes as VTK computes them, per cell of a file read by VTK's own readers.
std::vector<std::pair<int, double>> vtkVolumes(const QString &path, bool legacy)
{
    vtkSmartPointer<vtkDataSet> data;
    if (legacy) {
        vtkNew<vtkDataSetReader> reader;
        reader->SetFileName(path.toLocal8Bit().constData());
        reader->Update();
        data = reader->GetOutput();
    } else {
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(path.toLocal8Bit().constData());
        reader->Update();
        data = reader->GetOutput();
    }
    vtkNew<vtkCellSizeFilter> sizes;
    sizes->SetInputData(data);
    sizes->ComputeVertexCountOff();
    sizes->ComputeLengthOff();
    sizes->ComputeAreaOff();
    sizes->ComputeVolumeOn();
    sizes->ComputeSumOff();
    sizes->Update();
    vtkDataSet *out = vtkDataSet::SafeDownCast(sizes->GetOutputDataObject(0));
    vtkDataArray *volume = out->GetCellData()->GetArray("Volume");
    std::vector<std::pair<int, double>> result;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
        result.push_back({out->GetCellType(c), volume->GetComponent(c, 0)});
    return result;
}

// Values with six decimals at most, which VTK's ASCII writer (11 significant digits) keeps.
VolumeMesh withSixDecimals(VolumeMesh m)
{
    auto round = [](double v) { return std::round(v * 1e6) / 1e6; };
    for (Vec3 &p : m.points)
        p = Vec3(round(p.x()), round(p.y()), round(p.z()));
    for (double &q : m.cellQuality)
        q = round(q);
    return m;
}

// `mesh` through our .vtu or .vtp writer, VTK's XML reader, then VTK's own legacy writer.
void writeWithVtk(const VolumeMesh &mesh, const QString &dir, const QString &out, bool poly,
                  int version, bool binary)
{
    const QString xml = dir + (poly ? "/source.vtp" : "/source.vtu");
    writeVtk(mesh, xml.toStdString(), poly ? VtkFileKind::Vtp : VtkFileKind::Vtu);
    vtkSmartPointer<vtkDataWriter> writer;
    if (poly) {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName(xml.toLocal8Bit().constData());
        reader->Update();
        auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
        w->SetInputData(reader->GetOutput());
        writer = w;
    } else {
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(xml.toLocal8Bit().constData());
        reader->Update();
        auto w = vtkSmartPointer<vtkUnstructuredGridWriter>::New();
        w->SetInputData(reader->GetOutput());
        writer = w;
    }
    writer->SetFileName(out.toLocal8Bit().constData());
    writer->SetFileVersion(version);
    if (binary)
        writer->SetFileTypeToBinary();
    QVERIFY(writer->Write() == 1);
}

} // namespace

class TestVtk : public QObject {
    Q_OBJECT

private slots:
    void hybridRoundTrip_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("vtu") << int(VtkFileKind::Vtu);
        QTest::newRow("legacy vtk") << int(VtkFileKind::LegacyVtk);
    }
    void hybridRoundTrip()
    {
        QFETCH(int, kind);
        QTemporaryDir dir;
        VolumeMesh m = test::hybridMesh();
        m.regionBoundaries = regionSidesFromCells(m);
        m.zPositiveDepth = true;
        const QString path = dir.filePath("hybrid." + extensionOf(VtkFileKind(kind)));
        writeVtk(m, path.toStdString(), VtkFileKind(kind));
        const VolumeMesh back = readVtk(path.toStdString());
        const std::string diff = test::compareMeshes(m, back);
        QVERIFY2(diff.empty(), diff.c_str());
        QCOMPARE(back.name, m.name);
        QVERIFY(back.zPositiveDepth);
        // Point order is kept too.
        QCOMPARE(back.points, m.points);
    }

    void legacyFileIsVersion42()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("h.vtk");
        writeVtk(test::hybridMesh(), path.toStdString(), VtkFileKind::LegacyVtk);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readLine(), QByteArray("# vtk DataFile Version 4.2\n"));
        const QByteArray text = f.readAll();
        QVERIFY(text.contains("POINTS 13 double"));
        QVERIFY(text.contains("BINARY"));
    }

    void vtkComputesPositiveVolumes_data()
    {
        QTest::addColumn<bool>("legacy");
        QTest::newRow("vtu") << false;
        QTest::newRow("legacy vtk") << true;
    }
    void vtkComputesPositiveVolumes()
    {
        QFETCH(bool, legacy);
        QTemporaryDir dir;
        const VolumeMesh m = test::hybridMesh();
        const QString path = dir.filePath(legacy ? "h.vtk" : "h.vtu");
        writeVtk(m, path.toStdString(), legacy ? VtkFileKind::LegacyVtk : VtkFileKind::Vtu);
        const auto volumes = vtkVolumes(path, legacy);
        int tets = 0, pyramids = 0, wedges = 0;
        double total = 0;
        for (const auto &[type, volume] : volumes) {
            if (type != VTK_TETRA && type != VTK_PYRAMID && type != VTK_WEDGE)
                continue;
            tets += type == VTK_TETRA;
            pyramids += type == VTK_PYRAMID;
            wedges += type == VTK_WEDGE;
            QVERIFY2(volume > 0,
                     qPrintable(QString("VTK type %1 volume %2").arg(type).arg(volume)));
            total += volume;
        }
        QCOMPARE(tets, 2);
        QCOMPARE(pyramids, 5);
        QCOMPARE(wedges, 2);
        QVERIFY(std::abs(total - 2.0) < 1e-6); // the two unit cubes
    }

    void surfaceModelAsPolyData()
    {
        LayeredBoxParams p;
        p.fault = true;
        p.faultThrow = 30;
        p.edgeLength = 200;
        const Model model = recoverTopology(layeredBox(p));
        const VolumeMesh mesh = meshFromModel(model);
        QTemporaryDir dir;
        for (VtkFileKind kind : {VtkFileKind::Vtp, VtkFileKind::Vtu, VtkFileKind::LegacyVtk}) {
            const QString path = dir.filePath("model." + extensionOf(kind));
            writeVtk(mesh, path.toStdString(), kind);
            const VolumeMesh back = readVtk(path.toStdString());
            const std::string diff = test::compareMeshes(mesh, back);
            QVERIFY2(diff.empty(),
                     qPrintable(extensionOf(kind) + ": " + QString::fromStdString(diff)));
            const std::string modelDiff = test::compareModels(model, modelFromMesh(back));
            QVERIFY2(modelDiff.empty(), modelDiff.c_str());
        }
    }

    // Legacy files of VTK's own writers, each version and encoding, read by our parser: the same
    // mesh as the one they were written from (ASCII with values VTK's ASCII writer keeps; its
    // NaN quality off the volume cells written "nan", which VTK's reader could not read back).
    void filesOfVtkItselfAreRead_data()
    {
        QTest::addColumn<bool>("poly");
        QTest::addColumn<int>("version");
        QTest::addColumn<bool>("binary");
        for (bool poly : {false, true})
            for (int version : {42, 51})
                for (bool binary : {false, true})
                    QTest::newRow(qPrintable(QString("%1 %2 %3")
                                                 .arg(poly ? "poly data" : "grid")
                                                 .arg(version)
                                                 .arg(binary ? "binary" : "ascii")))
                        << poly << version << binary;
    }
    void filesOfVtkItselfAreRead()
    {
        QFETCH(bool, poly);
        QFETCH(int, version);
        QFETCH(bool, binary);
        QTemporaryDir dir;
        VolumeMesh m;
        if (poly) {
            LayeredBoxParams p;
            p.fault = true;
            p.faultThrow = 30;
            p.edgeLength = 200;
            m = meshFromModel(recoverTopology(layeredBox(p)));
        } else {
            m = test::hybridMesh();
            m.regionBoundaries = regionSidesFromCells(m);
        }
        if (!binary)
            m = withSixDecimals(m);
        const QString path = dir.filePath("vtk.vtk");
        writeWithVtk(m, dir.path(), path, poly, version, binary);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readLine(), QByteArray(version == 42 ? "# vtk DataFile Version 4.2\n"
                                                        : "# vtk DataFile Version 5.1\n"));
        QCOMPARE(f.readAll().contains("OFFSETS vtktypeint64"), version == 51);
        VolumeMesh back;
        try {
            back = readVtk(path.toStdString());
        } catch (const std::exception &e) {
            QFAIL(e.what());
        }
        const std::string diff = test::compareMeshes(m, back);
        QVERIFY2(diff.empty(), diff.c_str());
        QCOMPARE(back.name, m.name);
        QCOMPARE(back.points, m.points);
    }

    // Legacy files mean what VTK's own reader made of them (each checked against VTK 9.1's
    // reader when our parser replaced it): poly data cells come vertices, lines, polygons, then
    // strips whatever the file's order; only the first SCALARS of a section counts; a later FIELD
    // array replaces an array of its name.
    void legacyFilesMeanWhatVtkMakesOfThem()
    {
        QTemporaryDir dir;
        const QByteArray points = "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n";
        const QString poly = dir.filePath("poly.vtk");
        QFile f(poly);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("# vtk DataFile Version 4.2\norder\nASCII\nDATASET POLYDATA\n" + points
                + "POLYGONS 2 8\n3 0 1 2\n3 1 3 2\nLINES 2 7\n2 0 1\n3 1 3 2\nVERTICES 2 4\n1 0\n1 "
                  "3\nCELL_DATA 6\nSCALARS Other int\nLOOKUP_TABLE default\n0 0 0 0 0 0\n"
                  "SCALARS LineId int\nLOOKUP_TABLE default\n9 9 9 9 9 9\nFIELD FieldData 2\n"
                  "SurfaceId 1 6 int\n-1 -1 -1 -1 4 5\nLineId 1 6 int\n-1 -1 2 3 -1 -1\n");
        f.close();
        const VolumeMesh mesh = readVtk(poly.toStdString());
        QCOMPARE(mesh.corners, (std::vector<int>{0, 3}));
        QCOMPARE(mesh.edges, (std::vector<std::array<int, 2>>{{0, 1}, {1, 3}, {3, 2}}));
        QCOMPARE(mesh.lineNames, (std::vector<std::string>{"line_3", "line_4"}));
        QCOMPARE(mesh.edgeLine, (std::vector<int>{0, 1, 1}));
        QCOMPARE(mesh.triangles.size(), std::size_t(2));
        QCOMPARE(mesh.triangleSurface, (std::vector<int>{0, 1}));

        const QString grid = dir.filePath("grid.vtk");
        QFile g(grid);
        QVERIFY(g.open(QIODevice::WriteOnly));
        g.write("# vtk DataFile Version 4.2\nscalars\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points
                + "CELLS 2 8\n3 0 1 2\n3 1 3 2\nCELL_TYPES 2\n5 5\nCELL_DATA 2\n"
                  "SCALARS Other int\nLOOKUP_TABLE default\n0 0\n"
                  "SCALARS SurfaceId int\nLOOKUP_TABLE default\n0 1\n");
        g.close();
        const VolumeMesh one = readVtk(grid.toStdString());
        QCOMPARE(one.surfaces.size(), std::size_t(1)); // the second SCALARS was not kept
        QCOMPARE(one.surfaces[0].name, std::string("grid"));
    }

    void polyDataRefusesCells()
    {
        QTemporaryDir dir;
        QVERIFY_THROWS_EXCEPTION(
            InputError,
            writeVtk(test::hybridMesh(), dir.filePath("x.vtp").toStdString(), VtkFileKind::Vtp));
        QVERIFY(!QFile::exists(dir.filePath("x.vtp")));
    }

    void unreadableFilesAreClearErrors()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.vtu");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("<VTKFile type=\"UnstructuredGrid\"> not really\n");
        f.close();
        try {
            readVtk(path.toStdString());
            QFAIL("read a broken file");
        } catch (const FileError &e) {
            QVERIFY2(std::string(e.what()).find(path.toStdString()) == 0, e.what());
        }
        QVERIFY_THROWS_EXCEPTION(FileError, readVtk(dir.filePath("missing.vtk").toStdString()));
    }

    void meshioReadsOurFiles_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("withLines");
        QTest::newRow("vtu") << int(VtkFileKind::Vtu) << true;
        QTest::newRow("legacy vtk") << int(VtkFileKind::LegacyVtk) << true;
        // No line names at all (nested spheres): meshio fails on an empty binary array.
        QTest::newRow("vtu without lines") << int(VtkFileKind::Vtu) << false;
    }
    void meshioReadsOurFiles()
    {
        QFETCH(int, kind);
        QFETCH(bool, withLines);
        const QString python = test::pythonWithMeshio();
        if (python.isEmpty())
            QSKIP("*** python3-meshio is not installed: independent reader check SKIPPED ***");
        QTemporaryDir dir;
        const QString path = dir.filePath("m." + extensionOf(VtkFileKind(kind)));
        VolumeMesh mesh = test::hybridMesh();
        if (!withLines) {
            mesh.edges.clear();
            mesh.edgeLine.clear();
            mesh.lineNames.clear();
        }
        writeVtk(mesh, path.toStdString(), VtkFileKind(kind));
        QProcess p;
        p.start(python,
                {"-c",
                 "import sys, meshio\n"
                 "m = meshio.read(sys.argv[1])\n"
                 "c = {}\n"
                 "for b in m.cells: c[b.type] = c.get(b.type, 0) + len(b.data)\n"
                 "r = [int(v) for a in m.cell_data['RegionId'] for v in a]\n"
                 "print(len(m.points), c.get('tetra',0), c.get('pyramid',0), c.get('wedge',0),"
                 " c.get('triangle',0), c.get('line',0), c.get('vertex',0), sum(1 for v in r if v "
                 "== 1))\n",
                 path});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(QString(p.readAllStandardOutput()).trimmed(),
                 withLines ? QStringLiteral("13 2 5 2 4 4 4 7")
                           : QStringLiteral("13 2 5 2 4 0 4 7"));
    }

    // meshio writes version 5.1 legacy files whose integer arrays have VTK's fixed-size type
    // names (vtktypeint32 for our RegionId); VTK 9.1's own reader refuses them, we read them.
    void meshiosLegacyFilesAreRead_data()
    {
        QTest::addColumn<bool>("binary");
        QTest::newRow("ascii") << false;
        QTest::newRow("binary") << true;
    }
    void meshiosLegacyFilesAreRead()
    {
        QFETCH(bool, binary);
        const QString python = test::pythonWithMeshio();
        if (python.isEmpty())
            QSKIP("*** python3-meshio is not installed: independent reader check SKIPPED ***");
        QTemporaryDir dir;
        const VolumeMesh mesh = test::hybridMesh();
        const QString ours = dir.filePath("ours.vtu"), theirs = dir.filePath("meshio.vtk");
        writeVtk(mesh, ours.toStdString(), VtkFileKind::Vtu);
        QProcess p;
        p.start(python, {"-c",
                         "import sys, meshio\n"
                         "m = meshio.read(sys.argv[1])\n"
                         "# legacy names cannot hold spaces ('scaled jacobian')\n"
                         "m.cell_data = {k: v for k, v in m.cell_data.items() if ' ' not in k}\n"
                         "m.write(sys.argv[2], binary=sys.argv[3] == '1')\n",
                         ours, theirs, binary ? "1" : "0"});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QFile f(theirs);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains("vtktypeint32"));
        const VolumeMesh back = readVtk(theirs.toStdString());
        QCOMPARE(back.points.size(), mesh.points.size());
        QCOMPARE(back.cells.size(), mesh.cells.size());
        QCOMPARE(back.cellRegion, mesh.cellRegion);
        QCOMPARE(back.triangles.size(), mesh.triangles.size());
    }
};

QTEST_GUILESS_MAIN(TestVtk)
#include "test_vtk.moc"
