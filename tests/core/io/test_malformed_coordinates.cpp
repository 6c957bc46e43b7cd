// Coordinates every reader refuses (issue 18): not finite, or beyond the 1e15 bound at which
// squared distances and volumes stay finite; each a FileError naming the file, the line where
// the format has lines, and the vertex as the file numbers it.
#include "bounded_read.h"
#include "common/error.h"
#include "io/coordinate_bound.h"
#include "io/mesh_reader.h"
#include "io/model_reader.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::testing;

namespace {

QByteArray tsurfWith(const QByteArray &vertex2)
{
    return "GOCAD TSurf 1\nHEADER {\nname: s\n}\nVRTX 1 0 0 0\n" + vertex2
           + "\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n";
}

QByteArray msh22With(const QByteArray &node2)
{
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n" + node2
           + "\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n";
}

} // namespace

class TestMalformedCoordinates : public QObject {
    Q_OBJECT

private slots:
    void refused_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        // Before: info exited 0 with area and quality null.
        QTest::newRow("ts 1e200") << "big.ts" << tsurfWith("VRTX 2 1e200 0 0") << 6
                                  << "x coordinate '1e200' is beyond the bound of 1e15";
        QTest::newRow("ts just beyond")
            << "big.ts" << tsurfWith("VRTX 2 0 0 -1.0000001e15") << 6 << "beyond the bound";
        QTest::newRow("ts inf") << "inf.ts" << tsurfWith("VRTX 2 0 inf 0") << 6 << "is not finite";
        // Before: no line, and "point 1" (0-based) where the file says node 2.
        QTest::newRow("msh 2.2 nan")
            << "nan.msh" << msh22With("2 nan 0 0") << 7 << "node 2: coordinate nan is not finite";
        QTest::newRow("msh 2.2 1e16")
            << "big.msh" << msh22With("2 0 1e16 0") << 7 << "node 2: coordinate 1e+16";
        QTest::newRow("msh 4.1 nan")
            << "nan41.msh"
            << QByteArray("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 "
                          "3\n1\n2\n3\n0 0 0\n"
                          "nan 0 0\n0 1 0\n$EndNodes\n")
            << 11 << "node 2: coordinate nan is not finite";
        QTest::newRow("ply nan")
            << "nan.ply"
            << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 1\nproperty "
                          "list uchar int vertex_indices\nend_header\n0 0 0\n1 nan 0\n0 1 "
                          "0\n3 0 1 2\n")
            << 11 << "vertex 1 (numbered from 0, as faces index it): coordinate nan";
        QTest::newRow("obj 1e200")
            << "big.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1e200 0\nf 1 2 3\n") << 3
            << "beyond the bound";
        QTest::newRow("off -1e200")
            << "big.off" << QByteArray("OFF\n3 1 0\n0 0 0\n-1e200 0 0\n0 1 0\n3 0 1 2\n") << 4
            << "beyond the bound";
        QTest::newRow("so 1e200")
            << "big.so"
            << QByteArray("GOCAD TSolid 1\nTVOLUME a\nVRTX 1 0 0 0\nVRTX 2 1e200 0 0\n"
                          "VRTX 3 0 1 0\nVRTX 4 0 0 1\nTETRA 1 2 3 4\nEND\n")
            << 4 << "VRTX 2: coordinate 1e+200 is beyond the bound";
        QTest::newRow("vtk 1e200")
            << "big.vtk"
            << QByteArray("# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                          "POINTS 3 double\n0 0 0\n1e200 0 0\n0 1 0\nCELLS 1 4\n3 0 1 "
                          "2\nCELL_TYPES 1\n5\n")
            << 7 << "point 1 (numbered from 0): coordinate 1e+200";
    }
    void refused()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), name, text);
        try {
            // STL and PLY are read as meshes only (convert), every other format as a model.
            if (name.endsWith(".ply") || name.endsWith(".stl"))
                readVolumeMesh(path);
            else
                readModel(path);
            QFAIL("read a file with a bad coordinate");
        } catch (const FileError &e) {
            QCOMPARE(e.file(), path);
            QCOMPARE(e.line(), line);
            QVERIFY2(QString::fromStdString(e.cause()).contains(cause), e.what());
        }
    }

    void theBoundItselfIsAccepted()
    {
        QTemporaryDir dir;
        const Model m =
            readModel(writeTestFile(dir.path(), "edge.ts", tsurfWith("VRTX 2 1e15 0 -1e15")));
        QCOMPARE(m.surfaces.front().vertices[1].x(), maxCoordinate);
    }
};

QTEST_GUILESS_MAIN(TestMalformedCoordinates)
#include "test_malformed_coordinates.moc"
