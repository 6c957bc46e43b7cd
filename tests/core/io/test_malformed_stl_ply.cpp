// STL and PLY (issue 18): an edge of three facets keeps its five vertices (OpenMesh unwelded it
// into nine), binary PLY that OpenMesh would change is refused, and malformed or truncated files
// are FileErrors with the line or the facet.
#include "bounded_read.h"
#include "common/error.h"
#include "io/mesh_reader.h"
#include "mesh/model_conversion.h"

#include <QDataStream>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::testing;

namespace {

// Three facets around the edge (0,0,0)-(1,0,0): a fin, as where a fault meets a horizon.
const double fin[3][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                             {{1, 0, 0}, {0, 0, 0}, {0, -1, 0}},
                             {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}};

QByteArray asciiStl(int facets = 3)
{
    QByteArray text = "solid fin\n";
    for (int f = 0; f < facets; ++f) {
        text += "  facet normal 0 0 0\n    outer loop\n";
        for (const auto &p : fin[f])
            text += "      vertex " + QByteArray::number(p[0]) + " " + QByteArray::number(p[1])
                    + " " + QByteArray::number(p[2]) + "\n";
        text += "    endloop\n  endfacet\n";
    }
    return text + "endsolid fin\n";
}

QByteArray binaryStl(quint32 announced = 3)
{
    QByteArray bytes(80, ' ');
    QDataStream out(&bytes, QIODevice::Append);
    out.setByteOrder(QDataStream::LittleEndian);
    out.setFloatingPointPrecision(QDataStream::SinglePrecision);
    out << announced;
    for (const auto &facet : fin) {
        out << 0.0f << 0.0f << 0.0f;
        for (const auto &p : facet)
            out << float(p[0]) << float(p[1]) << float(p[2]);
        out << quint16(0);
    }
    return bytes;
}

QByteArray binaryPly()
{
    QByteArray bytes = "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\n"
                       "property float y\nproperty float z\nelement face 3\n"
                       "property list uchar int vertex_indices\nend_header\n";
    QDataStream out(&bytes, QIODevice::Append);
    out.setByteOrder(QDataStream::LittleEndian);
    out.setFloatingPointPrecision(QDataStream::SinglePrecision);
    const float points[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    for (const auto &p : points)
        out << p[0] << p[1] << p[2];
    const qint32 faces[3][3] = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    for (const auto &f : faces)
        out << quint8(3) << f[0] << f[1] << f[2];
    return bytes;
}

} // namespace

class TestMalformedStlPly : public QObject {
    Q_OBJECT

private slots:
    void edgeOfThreeFacetsKeepsItsVertices_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("ascii") << asciiStl();
        QTest::newRow("binary") << binaryStl();
    }
    void edgeOfThreeFacetsKeepsItsVertices()
    {
        QFETCH(QByteArray, bytes);
        QTemporaryDir dir;
        const VolumeMesh mesh = readVolumeMesh(writeTestFile(dir.path(), "fin.stl", bytes));
        QCOMPARE(int(mesh.points.size()), 5);
        QCOMPARE(int(mesh.triangles.size()), 3);
        // The three facets share the two vertices of their common edge.
        for (const Triangle &t : mesh.triangles) {
            QCOMPARE(t[0] + t[1] - std::min(t[0], t[1]), std::max(t[0], t[1]));
            QVERIFY((t[0] == 0 || t[1] == 0) && (t[0] == 1 || t[1] == 1));
        }
        const Model model = modelFromMesh(mesh);
        QCOMPARE(int(model.surfaces.size()), 1);
        QCOMPARE(int(model.surfaces[0].vertices.size()), 5);
    }

    void binaryPlyThatOpenMeshWouldUnweldIsRefused()
    {
        QTemporaryDir dir;
        try {
            readVolumeMesh(writeTestFile(dir.path(), "fin.ply", binaryPly()));
            QFAIL("read a binary PLY whose edge OpenMesh unwelds");
        } catch (const FileError &e) {
            QVERIFY2(QString(e.what()).contains("non-manifold faces: 5 vertices in the file"),
                     e.what());
        }
    }

    void malformedFilesAreFileErrors_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        QByteArray truncated = asciiStl();
        truncated.chop(QByteArray("endsolid fin\n").size());
        QTest::newRow("stl without endsolid")
            << "cut.stl" << truncated << 23 << "file ends before endsolid";
        QByteArray cutFacet = asciiStl(1);
        cutFacet.truncate(cutFacet.indexOf("endloop"));
        QTest::newRow("stl cut in a facet")
            << "cut.stl" << cutFacet << 8 << "unexpected end of file";
        QByteArray four = asciiStl(1);
        four.replace("    endloop", "      vertex 1 1 1\n    endloop");
        QTest::newRow("stl facet of four")
            << "four.stl" << four << 7 << "facet 1 has more than three vertices";
        QByteArray flat = asciiStl(1);
        flat.replace("vertex 0 1 0", "vertex 1 0 0");
        QTest::newRow("stl degenerate")
            << "flat.stl" << flat << 8 << "facet 1 has two equal corners";
        QByteArray nan = asciiStl(2);
        nan.replace("vertex 0 -1 0", "vertex 0 nan 0");
        QTest::newRow("stl nan") << "nan.stl" << nan << 13
                                 << "facet 2: coordinate nan is not finite";
        QTest::newRow("stl not a number")
            << "word.stl" << asciiStl(1).replace("vertex 1 0 0", "vertex 1 x 0") << 5
            << "expected a coordinate";
        QTest::newRow("binary count beyond the file")
            << "big.stl" << binaryStl(2000000000) << 0 << "its header announces 2000000000 facets";
        QTest::newRow("binary truncated") << "cut.stl" << binaryStl().left(150) << 0 << "truncated";
        QTest::newRow("neither") << "x.stl" << QByteArray("hello\n") << 0 << "neither an ASCII STL";
        QByteArray hugePly = binaryPly();
        hugePly.replace("element vertex 5", "element vertex 3000000000");
        QTest::newRow("ply binary vertex count")
            << "big.ply" << hugePly << 3 << "element vertex declares 3000000000";
        QTest::newRow("ply ascii truncated")
            << "cut.ply"
            << QByteArray(
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                   "end_header\n0 0 0\n1 0 0\n")
            << 12 << "unexpected end of file";
        QTest::newRow("ply ascii face index")
            << "index.ply"
            << QByteArray(
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                   "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
            << 13 << "face uses vertex 7 of 3";
    }
    void malformedFilesAreFileErrors()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), name, bytes);
        const BoundedRead r = runBounded([&] { readVolumeMesh(path); });
        QVERIFY2(r.outcome == BoundedRead::FileErrorRaised,
                 (outcomeName(r.outcome) + (": " + r.message)).c_str());
        const QString where =
            QString::fromStdString(path) + (line > 0 ? ":" + QString::number(line) : "") + ": ";
        QVERIFY2(QString::fromStdString(r.message).startsWith(where), r.message.c_str());
        QVERIFY2(QString::fromStdString(r.message).contains(cause), r.message.c_str());
        QVERIFY(r.peakKiB < 200 * 1024);
    }
};

QTEST_GUILESS_MAIN(TestMalformedStlPly)
#include "test_malformed_stl_ply.moc"
