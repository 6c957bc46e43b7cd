// OBJ and OFF single surfaces read through OpenMesh, and readModel() dispatching on extensions.
#include "common/error.h"
#include "io/model_reader.h"
#include "io/surface_mesh_reader.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <string>

using namespace stratamesh;

namespace {

std::string writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &content)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(content) != content.size())
        qFatal("cannot write %s", qPrintable(path));
    return path.toStdString();
}

// A unit square as a quad plus a triangle beside it; the 5th vertex is unused.
const QByteArray kObj = "# square and triangle\n"
                        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 7 7 7\nv 2 0 0.5\n"
                        "f 1 2 3 4\n"
                        "f 2 6 3\n";

const QByteArray kOff = "OFF\n"
                        "4 2 0\n"
                        "0 0 0\n1 0 0\n1 1 0\n1600649.31 2 -3.25\n"
                        "3 0 1 2\n"
                        "3 0 2 3\n";

void expectFileError(const std::string &path, const std::string &cause)
{
    try {
        readModel(path);
    } catch (const FileError &e) {
        QCOMPARE(e.file(), path);
        QVERIFY2(std::string(e.what()).find(cause) != std::string::npos, e.what());
        return;
    }
    QFAIL("no FileError raised");
}

double area(const Surface &s)
{
    double a = 0.0;
    for (const Triangle &t : s.triangles) {
        const Vec3 u = s.vertices[t[1]] - s.vertices[t[0]];
        const Vec3 v = s.vertices[t[2]] - s.vertices[t[0]];
        a += 0.5 * std::sqrt(u.squaredNorm() * v.squaredNorm() - u.dot(v) * u.dot(v));
    }
    return a;
}

} // namespace

class TestSurfaceMeshReader : public QObject {
    Q_OBJECT

private slots:
    void readsObj()
    {
        QTemporaryDir dir;
        const Model m = readModel(writeFile(dir, "patch.obj", kObj));
        QCOMPARE(m.name, std::string("patch"));
        QVERIFY(m.regions.empty());
        QVERIFY(m.universe.empty());
        QCOMPARE(m.surfaces.size(), std::size_t(1));
        const Surface &s = m.surfaces[0];
        QCOMPARE(s.name, std::string("patch"));
        QCOMPARE(s.type, FeatureType::Unknown);
        QCOMPARE(s.triangles.size(), std::size_t(3)); // the quad is split in two
        QCOMPARE(s.vertices.size(), std::size_t(5));  // unused vertex dropped
        QCOMPARE(s.vertices[4], Vec3(2, 0, 0.5));
        QVERIFY(qAbs(area(s) - (1.0 + 0.5 * std::sqrt(1.25))) < 1e-12);
        for (const Triangle &t : s.triangles)
            for (int v : t)
                QVERIFY(v >= 0 && v < 5);
    }

    void readsOffInDoublePrecision()
    {
        QTemporaryDir dir;
        const Model m = readModel(writeFile(dir, "Grid.OFF", kOff));
        const Surface &s = m.surfaces[0];
        QCOMPARE(s.name, std::string("Grid"));
        QCOMPARE(s.triangles.size(), std::size_t(2));
        QCOMPARE(s.triangles[0], (Triangle{0, 1, 2}));
        QCOMPARE(s.triangles[1], (Triangle{0, 2, 3}));
        QCOMPARE(s.vertices[3], Vec3(1600649.31, 2, -3.25)); // a float would lose the decimals
    }

    void fileWithoutTriangles()
    {
        QTemporaryDir dir;
        expectFileError(writeFile(dir, "points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
                        "no triangle");
    }

    void nonFiniteCoordinate()
    {
        QTemporaryDir dir;
        // OpenMesh alone would skip this line and shift the later vertex indices.
        expectFileError(writeFile(dir, "nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"),
                        "non-finite");
        try {
            readModel(writeFile(dir, "inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n"));
            QFAIL("no FileError raised");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), 5);
        }
    }

    void facesOpenMeshWouldDrop()
    {
        QTemporaryDir dir;
        const std::string degenerate =
            writeFile(dir, "degenerate.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 2\n");
        expectFileError(degenerate, "uses vertex 2 twice");
        try {
            readModel(degenerate);
        } catch (const FileError &e) {
            QCOMPARE(e.line(), 5);
        }
        // Three triangles on one edge: OpenMesh would duplicate vertices (a silent cut).
        expectFileError(writeFile(dir, "fin.obj",
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                  "f 1 2 3\nf 2 1 4\nf 1 2 5\n"),
                        "non-manifold");
    }

    void offVertexLineWithExtraWords()
    {
        QTemporaryDir dir;
        // A colour after the coordinates: read word by word, as OpenMesh does, the 999999999
        // became the next vertex's x and a later word a face of that many corners.
        const Model m =
            readModel(writeFile(dir, "extra.off",
                                "OFF\n4 2 0\n0 0 0 999999999\n1 0 0 7\n1 1 0\n0 1 0 5 5\n"
                                "3 0 1 2\n3 0 2 3 1 1 1\n"));
        QCOMPARE(m.surfaces.size(), std::size_t(1));
        QCOMPARE(m.surfaces[0].vertices.size(), std::size_t(4));
        QCOMPARE(m.surfaces[0].triangles.size(), std::size_t(2));
        QCOMPARE(m.surfaces[0].vertices[3], Vec3(0, 1, 0));
        QCOMPARE(m.surfaces[0].triangles[1], (Triangle{0, 2, 3}));
    }

    void unreadableContent()
    {
        QTemporaryDir dir;
        expectFileError(writeFile(dir, "garbage.off", "this is not an OFF file\n"),
                        "not an OFF file");
        expectFileError(writeFile(dir, "short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"),
                        "file ends after 2 of 3 vertices");
    }

    void missingFile()
    {
        QTemporaryDir dir;
        expectFileError(dir.filePath("absent.obj").toStdString(), "cannot open");
        try {
            readSurfaceMesh(dir.filePath("absent.off").toStdString());
            QFAIL("no FileError raised");
        } catch (const FileError &e) {
            QVERIFY2(std::string(e.what()).find("absent.off") != std::string::npos, e.what());
        }
    }

    void dispatchesGocadByExtension()
    {
        QTemporaryDir dir;
        const std::string path =
            writeFile(dir, "one.TS",
                      "GOCAD TSurf 1\nHEADER {name:one}\nTFACE\n"
                      "VRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n");
        const Model m = readModel(path);
        QCOMPARE(m.surfaces.size(), std::size_t(1));
        QCOMPARE(m.surfaces[0].name, std::string("one"));
        QVERIFY(isReadableModelFile("a/b.Ml"));
        QVERIFY(isReadableModelFile("a/b.msh"));
        QVERIFY(!isReadableModelFile("a/b.stl"));
        expectFileError(writeFile(dir, "model.stl", "solid x\n"), "unknown model file extension");
    }

    // Issue 17: a FileError keeps the English pattern and its values for the GUI to translate;
    // its cause and what() are the filled English text, as before.
    void fileErrorKeepsItsPattern()
    {
        const FileError made("m.off", 4, MessageText{"coordinate '%1' is not a number", {"nope"}});
        QCOMPARE(made.cause(), std::string("coordinate 'nope' is not a number"));
        QCOMPARE(made.text().pattern, std::string("coordinate '%1' is not a number"));
        QCOMPARE(made.text().args, std::vector<std::string>{"nope"});
        QCOMPARE(std::string(made.what()),
                 std::string("m.off:4: coordinate 'nope' is not a number"));
        const FileError plain("m.off", 0, "empty file");
        QCOMPARE(plain.cause(), std::string("empty file"));
        QVERIFY(plain.text().pattern.empty());

        QTemporaryDir dir;
        try {
            readModel(writeFile(dir, "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 nope\n0 1 0\n3 0 1 2\n"));
            QFAIL("no FileError raised");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), 4);
            QCOMPARE(e.cause(), std::string("coordinate 'nope' is not a number"));
            QCOMPARE(e.text().pattern, std::string("coordinate '%1' is not a number"));
            QCOMPARE(e.text().text(), e.cause());
        }
        // A coordinate out of bounds: its problem is a sentence of its own, translated apart.
        try {
            readModel(writeFile(dir, "far.off", "OFF\n3 1 0\n0 0 0\n1 0 1e300\n0 1 0\n3 0 1 2\n"));
            QFAIL("no FileError raised");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), 4);
            QCOMPARE(e.text().pattern, std::string("coordinate '%1' %2"));
            QCOMPARE(e.text().args, std::vector<std::string>{"1e300"});
            QCOMPARE(e.text().parts.size(), std::size_t(1));
            QCOMPARE(e.text().parts[0].pattern,
                     std::string("is beyond the bound of 1e15 that keeps squared distances and "
                                 "volumes finite"));
            QCOMPARE(e.cause(), std::string("coordinate '1e300' is beyond the bound of 1e15 that "
                                            "keeps squared distances and volumes finite"));
        }
    }
};

QTEST_GUILESS_MAIN(TestSurfaceMeshReader)
#include "test_surface_mesh_reader.moc"
