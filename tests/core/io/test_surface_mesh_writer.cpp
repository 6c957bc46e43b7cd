// One surface as OBJ, OFF, PLY (coordinates bit-exact in the text) and STL (32-bit floats by
// design); OpenMesh, an independent reader, loads every file with the same counts and faces; a
// model with several surfaces needs a choice; STL refuses non-manifold input.
#include "common/error.h"
#include "io/mesh_reader.h"
#include "io/model_reader.h"
#include "io/surface_mesh_writer.h"
#include "test_roundtrip_meshes.h"

#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__) // clang has no such warning group
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

Model wavySurface()
{
    Model model;
    model.name = "wavy";
    Surface s;
    s.name = "h1";
    const int n = 6;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            s.vertices.push_back(
                {1600649.31 + i / 3.0, 720000.1 + j / 7.0, std::sin(i * 0.7) * std::cos(j * 1.3)});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            s.triangles.push_back({a, a + 1, a + n + 2});
            s.triangles.push_back({a, a + n + 2, a + n + 1});
        }
    model.surfaces.push_back(s);
    return model;
}

// Vertex coordinates parsed from the text with strtod, independently of the writer.
std::vector<Vec3> coordinatesInText(const QString &path, const QString &extension)
{
    QFile f(path);
    std::vector<Vec3> out;
    if (!f.open(QIODevice::ReadOnly))
        return out;
    const QList<QByteArray> lines = f.readAll().split('\n');
    int first = 0, count = 0;
    if (extension == "obj") {
        for (const QByteArray &l : lines)
            if (l.startsWith("v ")) {
                const QList<QByteArray> t = l.split(' ');
                out.push_back({std::strtod(t[1].constData(), nullptr),
                               std::strtod(t[2].constData(), nullptr),
                               std::strtod(t[3].constData(), nullptr)});
            }
        return out;
    }
    if (extension == "off") {
        first = 2;
        count = lines[1].split(' ')[0].toInt();
    } else {
        for (int i = 0; i < lines.size(); ++i) {
            if (lines[i].startsWith("element vertex"))
                count = lines[i].split(' ')[2].toInt();
            if (lines[i] == "end_header")
                first = i + 1;
        }
    }
    for (int i = first; i < first + count; ++i) {
        const QList<QByteArray> t = lines[i].split(' ');
        out.push_back({std::strtod(t[0].constData(), nullptr),
                       std::strtod(t[1].constData(), nullptr),
                       std::strtod(t[2].constData(), nullptr)});
    }
    return out;
}

Mesh readBack(const QString &path)
{
    Mesh mesh;
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::read_mesh(mesh, path.toStdString(), options))
        qWarning("OpenMesh could not read %s", qPrintable(path));
    return mesh;
}

} // namespace

class TestSurfaceMeshWriter : public QObject {
    Q_OBJECT

private slots:
    void exactFormats_data()
    {
        QTest::addColumn<QString>("extension");
        QTest::newRow("obj") << "obj";
        QTest::newRow("off") << "off";
        QTest::newRow("ply") << "ply";
    }
    void exactFormats()
    {
        QFETCH(QString, extension);
        const Model model = wavySurface();
        QTemporaryDir dir;
        const QString path = dir.filePath("s." + extension);
        writeSurfaceMesh(model, path.toStdString());
        const Mesh mesh = readBack(path);
        const Surface &s = model.surfaces[0];
        QCOMPARE(int(mesh.n_vertices()), int(s.vertices.size()));
        QCOMPARE(int(mesh.n_faces()), int(s.triangles.size()));
        // OpenMesh 9 reads these coordinates as floats: equal to float precision.
        for (std::size_t v = 0; v < s.vertices.size(); ++v) {
            const auto p = mesh.point(Mesh::VertexHandle(int(v)));
            for (int k = 0; k < 3; ++k)
                QCOMPARE(float(p[k]), float(s.vertices[v][k]));
        }
        // The text itself holds the exact doubles.
        const std::vector<Vec3> exact = coordinatesInText(path, extension);
        QCOMPARE(exact, s.vertices);
        int f = 0;
        for (const auto fh : mesh.faces()) {
            std::vector<int> ids;
            for (const auto vh : mesh.fv_range(fh))
                ids.push_back(vh.idx());
            const Triangle &t = s.triangles[f++];
            // Same cycle (OpenMesh may start the face at another corner).
            const bool same = (ids[0] == t[0] && ids[1] == t[1])
                              || (ids[0] == t[1] && ids[1] == t[2])
                              || (ids[0] == t[2] && ids[1] == t[0]);
            QVERIFY(same);
        }
        // And our own reading paths give everything back exactly.
        const Model back = extension == "ply" ? readMeshAsModel(path.toStdString())
                                              : readModel(path.toStdString());
        QCOMPARE(back.surfaces.at(0).vertices, s.vertices);
        QCOMPARE(back.surfaces.at(0).triangles, s.triangles);
    }

    void stlKeepsFloats()
    {
        const Model model = wavySurface();
        QTemporaryDir dir;
        const QString path = dir.filePath("s.stl");
        writeSurfaceMesh(model, path.toStdString());
        QCOMPARE(QFileInfo(path).size(),
                 qint64(84 + 50 * model.surfaces[0].triangles.size())); // binary STL
        const Mesh mesh = readBack(path);
        QCOMPARE(int(mesh.n_faces()), int(model.surfaces[0].triangles.size()));
        QCOMPARE(int(mesh.n_vertices()), int(model.surfaces[0].vertices.size()));
        for (const auto vh : mesh.vertices()) {
            const auto p = mesh.point(vh);
            QVERIFY(p[0] == double(float(p[0])) && p[2] == double(float(p[2])));
        }
        // readMeshAsModel() opens it too: same triangles, corners at the float positions.
        const Model back = readMeshAsModel(path.toStdString());
        const Surface &s = model.surfaces[0];
        QCOMPARE(back.surfaces.at(0).triangles.size(), s.triangles.size());
        QCOMPARE(back.surfaces.at(0).vertices.size(), s.vertices.size());
        for (std::size_t t = 0; t < s.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c)
                    QCOMPARE(back.surfaces[0].vertices[back.surfaces[0].triangles[t][k]][c],
                             double(float(s.vertices[s.triangles[t][k]][c])));
    }

    void choosingAmongSeveralSurfaces()
    {
        Model model = wavySurface();
        model.surfaces.push_back(model.surfaces[0]);
        model.surfaces[1].name = "h2";
        for (Vec3 &p : model.surfaces[1].vertices)
            p.z() += 10;
        QTemporaryDir dir;
        const QString path = dir.filePath("two.obj");
        QVERIFY_THROWS_EXCEPTION(InputError, writeSurfaceMesh(model, path.toStdString()));
        QVERIFY(!QFile::exists(path));
        writeSurfaceMesh(model, path.toStdString(), 1);
        QCOMPARE(coordinatesInText(path, "obj"), model.surfaces[1].vertices);
    }

    void refusals()
    {
        QTemporaryDir dir;
        Model model = wavySurface();
        // Three triangles on one edge: OpenMesh cannot hold it.
        Surface &s = model.surfaces[0];
        s.vertices.push_back({0, 0, 5});
        s.triangles.push_back({0, 1, int(s.vertices.size()) - 1});
        s.vertices.push_back({0, 0, -5});
        s.triangles.push_back({1, 0, int(s.vertices.size()) - 1});
        QVERIFY_THROWS_EXCEPTION(InputError,
                                 writeSurfaceMesh(model, dir.filePath("x.stl").toStdString()));
        QVERIFY_THROWS_EXCEPTION(
            FileError, writeSurfaceMesh(wavySurface(), dir.filePath("x.xyz").toStdString()));
        QVERIFY(QDir(dir.path()).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestSurfaceMeshWriter)
#include "test_surface_mesh_writer.moc"
