// The class of hostile input (issue 18), across readers: negative counts, counts that disagree
// with the data or exceed the file, truncated files, ids out of range, repeated nodes, empty
// models. Every file here is under 1 KB, and each must end in a FileError ("file:line: cause")
// within 200 MB and a few seconds, read in a forked child under an address-space cap.
#include "bounded_read.h"
#include "common/error.h"
#include "io/mesh_reader.h"
#include "io/model_reader.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::testing;

namespace {

const QByteArray msh22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
const QByteArray threeNodes = "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n";
const QByteArray vtkHead = "# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n";
const QByteArray vtkTriangle =
    "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n";

QByteArray vtu(const QByteArray &points)
{
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\">\n<UnstructuredGrid>\n"
           "<Piece NumberOfPoints=\""
           + points
           + "\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float64\" "
             "NumberOfComponents=\"3\" "
             "format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray>\n</Points>\n<Cells>\n<DataArray "
             "type=\"Int64\" "
             "Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n<DataArray type=\"Int64\" "
             "Name=\"offsets\" format=\"ascii\">3</DataArray>\n<DataArray type=\"UInt8\" "
             "Name=\"types\" "
             "format=\"ascii\">5</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</"
             "VTKFile>\n";
}

} // namespace

class TestMalformedInputs : public QObject {
    Q_OBJECT

private slots:
    void fileErrorWithinBounds_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("line"); // 0: the format has no line to name
        QTest::addColumn<QString>("cause");
        // Gocad
        QTest::newRow("ts empty file") << "empty.ts" << QByteArray() << 0 << "empty file";
        QTest::newRow("ts triangle to an undefined vertex")
            << "ref.ts"
            << QByteArray(
                   "GOCAD TSurf 1\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 9\nEND\n")
            << 5 << "TRGL refers to vertex 9";
        QTest::newRow("ts truncated")
            << "cut.ts"
            << QByteArray("GOCAD TSurf 1\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\n"
                          "TRGL 1 2 3\n")
            << 5 << "file ends before the END";
        QTest::newRow("ml empty model")
            << "empty.ml" << QByteArray("GOCAD Model3d 1\nHEADER {\nname: m\n}\nEND\n") << 0
            << "empty model";
        QTest::newRow("so no tetrahedron")
            << "empty.so" << QByteArray("GOCAD TSolid 1\nTVOLUME a\nVRTX 1 0 0 0\nEND\n") << 0
            << "empty model";
        QTest::newRow("so repeated vertex")
            << "flat.so"
            << QByteArray("GOCAD TSolid 1\nTVOLUME a\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 "
                          "0\nVRTX 4 0 0 1\n"
                          "TETRA 1 2 3 3\nEND\n")
            << 7 << "TETRA uses the same vertex twice";
        // Gmsh
        QTest::newRow("msh only a format") << "format.msh" << msh22 << 0 << "empty model";
        QTest::newRow("msh nodes only") << "nodes.msh" << msh22 + threeNodes << 0 << "empty model";
        QTest::newRow("msh triangle repeating a node")
            << "flat.msh" << msh22 + threeNodes + "$Elements\n1\n1 2 2 1 1 1 2 2\n$EndElements\n"
            << 12 << "the triangle uses node 2 twice";
        QTest::newRow("msh element short of nodes")
            << "short.msh" << msh22 + threeNodes + "$Elements\n1\n1 2 2 1 1 1 2\n$EndElements\n"
            << 12 << "a triangle needs 3 nodes";
        QTest::newRow("msh section never ended") << "open.msh" << msh22 + "$Comments\nhello\n"
                                                 << 4 << "section $Comments has no $EndComments";
        QTest::newRow("msh binary")
            << "bin.msh" << QByteArray("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n") << 2
            << "binary MSH files are not supported";
        // VTK
        QTest::newRow("vtk negative field id")
            << "neg.vtk"
            << vtkHead + vtkTriangle + "CELL_DATA 1\nFIELD FieldData 1\nSurfaceId 1 1 int\n-7\n"
            << 0 << "cell 0 has SurfaceId -7";
        QTest::newRow("vtk point id out of range")
            << "idx.vtk"
            << QByteArray("# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 "
                          "double\n0 0 0 1 0 0 0 "
                          "1 0\nPOLYGONS 1 4\n3 0 1 5\n")
            << 8 << "cell 0 uses point 5 of 3";
        QTest::newRow("vtk cell data count")
            << "data.vtk"
            << vtkHead + vtkTriangle
                   + "CELL_DATA 2\nSCALARS SurfaceId int 1\nLOOKUP_TABLE default\n0 0\n"
            << 13 << "CELL_DATA declares 2 values, the cell section at line 9 declares 1";
        QTest::newRow("vtk binary garbage")
            << "bin.vtk"
            << QByteArray("# vtk DataFile Version 4.2\nx\nBINARY\nDATASET "
                          "UNSTRUCTURED_GRID\nPOINTS 3 double\nabc\n")
            << 5 << "POINTS data is cut short: 9 values of 8 bytes, 4 bytes are left";
        QTest::newRow("vtu 2e9 points") << "huge.vtu" << vtu("2000000000") << 4
                                        << "NumberOfPoints is 2000000000, more than the file";
        QTest::newRow("vtu negative points")
            << "neg.vtu" << vtu("-3") << 4 << "NumberOfPoints is negative";
        QTest::newRow("vtu truncated")
            << "cut.vtu" << vtu("3").left(200) << 0 << "VTK cannot read it";
        // OBJ / OFF
        QTest::newRow("obj index 0")
            << "zero.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n") << 4
            << "face uses vertex 0";
        QTest::newRow("obj index beyond")
            << "big.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n") << 4
            << "face uses vertex 99999999999, the file defines 3";
        QTest::newRow("obj relative index beyond")
            << "rel.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n") << 4
            << "face uses vertex -9";
        QTest::newRow("obj no face") << "noface.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
                                     << 0 << "no triangle in the file";
        QTest::newRow("off face of 2e9 vertices")
            << "bigface.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n")
            << 6 << "a face of 2000000000 vertices lists 3";
        QTest::newRow("off vertex count beyond")
            << "count.off" << QByteArray("OFF\n2000000000 1 0\n0 0 0\n") << 3
            << "file ends after 1 of 2000000000 vertices";
        QTest::newRow("off negative count")
            << "neg.off" << QByteArray("OFF\n-3 1 0\n") << 2 << "invalid vertex and face counts";
        QTest::newRow("off face index")
            << "idx.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n") << 6
            << "face vertex '7' is not an index from 0 to 2";
        QTest::newRow("off fewer faces")
            << "few.off" << QByteArray("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") << 6
            << "file ends after 1 of 2 faces";
        // PLY / STL
        QTest::newRow("ply list longer than its line")
            << "list.ply"
            << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty "
                          "float y\nproperty "
                          "float z\nelement face 1\nproperty list uchar int "
                          "vertex_indices\nend_header\n0 0 0\n1 0 "
                          "0\n0 1 0\n2000000000 0 1 2\n")
            << 13 << "line too short for its list";
        QTest::newRow("ply element count beyond")
            << "count.ply"
            << QByteArray("ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float "
                          "x\nend_header\n")
            << 3 << "the element count is 2000000000, more than the remaining";
        QTest::newRow("stl not an stl")
            << "x.stl" << QByteArray("hello\n") << 0 << "neither an ASCII STL";
        QTest::newRow("garbage ts")
            << "garbage.ts" << QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) << 1
            << "not a Gocad file";
        QTest::newRow("gm not a zip") << "x.gm" << QByteArray("PK\x03\x04 not really", 15) << 0
                                      << "not a readable zip archive";
    }
    void fileErrorWithinBounds()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QVERIFY(bytes.size() < 1024);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), name, bytes);
        // STL and PLY are read as meshes only (convert), every other format as a model.
        const bool meshOnly = name.endsWith(".stl") || name.endsWith(".ply");
        const BoundedRead r =
            runBounded([&] { meshOnly ? void(readVolumeMesh(path)) : void(readModel(path)); });
        qInfo("%s: %s in %.3f s, +%ld KiB", qPrintable(name), outcomeName(r.outcome), r.seconds,
              r.peakKiB);
        QVERIFY2(r.outcome == BoundedRead::FileErrorRaised,
                 (outcomeName(r.outcome) + (": " + r.message)).c_str());
        const QString where =
            QString::fromStdString(path) + (line > 0 ? ":" + QString::number(line) : "") + ": ";
        QVERIFY2(QString::fromStdString(r.message).startsWith(where), r.message.c_str());
        QVERIFY2(QString::fromStdString(r.message).contains(cause), r.message.c_str());
        QVERIFY2(r.peakKiB < 200 * 1024, qPrintable(QString::number(r.peakKiB) + " KiB"));
        QVERIFY(r.seconds < 5);
    }
};

QTEST_GUILESS_MAIN(TestMalformedInputs)
#include "test_malformed_inputs.moc"
