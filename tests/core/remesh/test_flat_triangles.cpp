// Flat triangles of a finished remesh split away at their apex (flat_triangles.h).
#include "model/topology.h"
#include "model/validity.h"
#include "quality/triangle_quality.h"
#include "remesh/flat_triangles.h"

#include <QtTest>

#include <algorithm>

using namespace stratamesh;

namespace {

Surface surface(const std::string &name, std::vector<Vec3> vertices,
                std::vector<Triangle> triangles)
{
    Surface s;
    s.name = name;
    s.featureName = name;
    s.vertices = std::move(vertices);
    s.triangles = std::move(triangles);
    return s;
}

// A horizontal surface A and a vertical surface B meeting along y = z = 0. B runs along the
// contact p → m → q; A has a flat triangle (p, m, q) on it and a triangle on the long edge p–q.
Model flatTriangleModel()
{
    const Vec3 p(0, 0, 0), m(1, 0, 0), q(2, 0, 0);
    Model model;
    model.surfaces.push_back(
        surface("A", {p, m, q, Vec3(0, 1, 0), Vec3(2, 1, 0)}, {{0, 1, 2}, {0, 2, 4}, {0, 4, 3}}));
    model.surfaces.push_back(surface("B", {p, m, q, Vec3(0, 0, -1), Vec3(2, 0, -1), Vec3(1, 0, -1)},
                                     {{1, 0, 3}, {1, 3, 5}, {2, 1, 5}, {2, 5, 4}}));
    return recoverTopology(std::move(model));
}

double widestAngle(const Model &model)
{
    double widest = 0.0;
    for (const Surface &s : model.surfaces)
        for (const Triangle &t : s.triangles) {
            const TriangleShape shape =
                triangleShape(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
            widest =
                std::max(widest, *std::max_element(shape.anglesDeg.begin(), shape.anglesDeg.end()));
        }
    return widest;
}

} // namespace

class TestFlatTriangles : public QObject {
    Q_OBJECT

private slots:
    void flatTriangleIsSplitAway()
    {
        Model model = flatTriangleModel();
        QVERIFY(widestAngle(model) > 179.9);
        ValidityReport validity = checkValidity(model);
        const std::size_t before = validity.problems.size();
        const FlatTriangleRepair r = mendFlatTriangles(model, validity);
        QCOMPARE(r.found, 1);
        QCOMPARE(r.mended, 1);
        QVERIFY(widestAngle(model) < 140.0);
        QVERIFY(validity.problems.size() <= before);
        QCOMPARE(validity.problems.size(), checkValidity(model).problems.size());
        // A keeps its area in 3 triangles, all using the edges p–m and m–q that B uses; B is
        // untouched.
        QCOMPARE(model.surfaces[0].triangles.size(), std::size_t(3));
        QCOMPARE(model.surfaces[1].triangles.size(), std::size_t(4));
        double area = 0.0;
        for (const Triangle &t : model.surfaces[0].triangles)
            area += triangleArea(model.surfaces[0].vertices[t[0]], model.surfaces[0].vertices[t[1]],
                                 model.surfaces[0].vertices[t[2]]);
        QCOMPARE(area, 2.0);
        // A's triangles still point up.
        for (const Triangle &t : model.surfaces[0].triangles) {
            const std::vector<Vec3> &v = model.surfaces[0].vertices;
            QVERIFY((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).z() > 0.0);
        }
        // The contact of A and B is one line through p, m and q.
        int contact = -1;
        for (std::size_t l = 0; l < model.lines.size(); ++l)
            if (model.lines[l].surfaces == std::vector<int>{0, 1})
                contact = static_cast<int>(l);
        QVERIFY(contact >= 0);
        QCOMPARE(model.lines[contact].vertices.size(), std::size_t(3));
        QCOMPARE(model.vertices.size(), std::size_t(8));
    }

    void nothingToDoLeavesTheModel()
    {
        Model model = flatTriangleModel();
        ValidityReport validity = checkValidity(model);
        QCOMPARE(mendFlatTriangles(model, validity, 170.0, 0).found, 0);
        QCOMPARE(model.surfaces[0].triangles.size(), std::size_t(3));
        QVERIFY(widestAngle(model) > 179.9);
        // An apex threshold above every angle finds nothing either.
        Model same = flatTriangleModel();
        QCOMPARE(mendFlatTriangles(same, validity, 180.5).found, 0);
        QCOMPARE(same.surfaces[0].triangles, model.surfaces[0].triangles);
    }
};

QTEST_GUILESS_MAIN(TestFlatTriangles)
#include "test_flat_triangles.moc"
