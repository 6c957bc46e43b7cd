// Line vertices as far apart as the surfaces beside them (remesh/line_spacing.h), on a flat strip
// between two contacts built in code: the strip is a row of needles while its lines are twice as
// dense as the surfaces on either side, and nothing moves when they are not.
#include "remesh/line_spacing.h"

#include "flat_soup_shape.h"
#include "remesh/intersection_repair.h"

#include <QtTest>

#include <vector>

using namespace stratamesh;

namespace {

struct Row {
    std::vector<int> ids;
};

Row addRow(OutputMesh &m, double y, const std::vector<double> &xs, std::vector<int> surfaces,
           std::vector<int> lines, int firstCorner)
{
    Row row;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        OutputPoint p;
        p.position = Vec3(xs[i], y, 0.0);
        p.surfaces = surfaces;
        p.lines = lines;
        if (firstCorner >= 0 && (i == 0 || i + 1 == xs.size()))
            p.corners = {firstCorner + (i == 0 ? 0 : 1)};
        m.points.push_back(p);
        row.ids.push_back(static_cast<int>(m.points.size()) - 1);
    }
    return row;
}

// Triangles between a lower and an upper row, advancing along x, normals +z.
void zip(OutputMesh &m, const Row &low, const Row &high, int surface)
{
    std::size_t i = 0, j = 0;
    auto x = [&](int v) { return m.points[v].position.x(); };
    while (i + 1 < low.ids.size() || j + 1 < high.ids.size()) {
        const bool lower = j + 1 >= high.ids.size()
                           || (i + 1 < low.ids.size() && x(low.ids[i + 1]) <= x(high.ids[j + 1]));
        if (lower) {
            m.triangles.push_back({{low.ids[i], low.ids[i + 1], high.ids[j]}, surface});
            ++i;
        } else {
            m.triangles.push_back({{low.ids[i], high.ids[j + 1], high.ids[j]}, surface});
            ++j;
        }
    }
}

std::vector<double> steps(double length, double step)
{
    std::vector<double> xs;
    for (int k = 0; k * step <= length + 1e-9; ++k)
        xs.push_back(k * step);
    return xs;
}

// Surfaces 1 (y ∈ [-1, 0]), 0 (the strip, y ∈ [0, width]) and 2 (above), 8 long; the two lines
// (0 at y = 0, 1 at y = width) have vertices every `lineStep`, the outer borders every 1.
OutputMesh strip(double width, double lineStep)
{
    OutputMesh m;
    const Row c = addRow(m, -1.0, steps(8.0, 1.0), {1}, {}, -1);
    const Row a = addRow(m, 0.0, steps(8.0, lineStep), {0, 1}, {0}, 0);
    const Row b = addRow(m, width, steps(8.0, lineStep), {0, 2}, {1}, 2);
    const Row d = addRow(m, width + 1.0, steps(8.0, 1.0), {2}, {}, -1);
    zip(m, c, a, 1);
    zip(m, a, b, 0);
    zip(m, b, d, 2);
    return m;
}

struct Shape {
    test::FlatSoupShape flat;
    double lineLength[2] = {0.0, 0.0};
};

Shape shapeOf(const EditableSoup &soup)
{
    Shape s{test::flatSoupShape(soup)};
    // The contacts: edges between the strip and a surface beside it, by the height they run at.
    for (int v = 0; v < soup.pointCount(); ++v)
        for (int w : soup.neighbours(v))
            if (v < w && soup.isFeatureEdge(v, w)
                && std::abs(soup.position(v).y() - soup.position(w).y()) < 1e-12) {
                const double y = soup.position(v).y();
                if (y > -0.5 && y < 1e-9)
                    s.lineLength[0] += (soup.position(w) - soup.position(v)).norm();
                else if (y > 1e-9 && y < 1.5 && soup.point(v).lines == std::vector<int>{1})
                    s.lineLength[1] += (soup.position(w) - soup.position(v)).norm();
            }
    return s;
}

} // namespace

class TestLineSpacing : public QObject {
    Q_OBJECT

private slots:
    void denseLinesAroundAStripOfNeedlesAreThinned()
    {
        EditableSoup soup(strip(1.0, 0.5));
        const Shape before = shapeOf(soup);
        // Every strip triangle and the half-cell ones beside it: 26.6°.
        QCOMPARE(before.flat.small, 64);
        const int removed = spaceLineVertices(soup);
        const Shape after = shapeOf(soup);
        qInfo("  %d line vertices removed, triangles under 30°: %d → %d", removed,
              before.flat.small, after.flat.small);
        QVERIFY(removed >= 8);
        QVERIFY(after.flat.small <= before.flat.small / 4);
        QCOMPARE(after.flat.flipped, 0);
        // Same surfaces, same area each, same two contacts end to end.
        QCOMPARE(after.flat.area.size(), std::size_t(3));
        for (const auto &[surface, area] : before.flat.area)
            QVERIFY(std::abs(after.flat.area.at(surface) - area) < 1e-9);
        QVERIFY(std::abs(after.lineLength[0] - 8.0) < 1e-9);
        QVERIFY(std::abs(after.lineLength[1] - 8.0) < 1e-9);
        for (int v = 0; v < soup.pointCount(); ++v)
            if (!soup.vertexTriangles(v).empty() && !soup.point(v).corners.empty())
                QCOMPARE(soup.vertexClass(v), VertexClass::Fixed);
    }

    void aCrossingAlreadyThereDoesNotUndoTheThinning()
    {
        // The collapses are undone when they add crossings; one the soup had before is not theirs.
        OutputMesh mesh = strip(1.0, 0.5);
        test::addUprightNeedle(mesh, 4.5, -0.93, 3);
        EditableSoup soup(mesh);
        QCOMPARE(soupIntersections(soup).size(), std::size_t(1));
        const int before = shapeOf(soup).flat.small;
        const int removed = spaceLineVertices(soup);
        qInfo("  %d line vertices removed beside a crossing, triangles under 30°: %d → %d", removed,
              before, shapeOf(soup).flat.small);
        QVERIFY(removed >= 8);
        QVERIFY(shapeOf(soup).flat.small <= before / 4);
        QCOMPARE(soupIntersections(soup).size(), std::size_t(1));
    }

    void collapsesThatWouldCrossAreLeftOut()
    {
        // A needle through a strip triangle, 0.1 from its edges, where the thinned strip has the
        // edge from (4.5, 0) to (3.5, 1): left there it would cross the two triangles of that edge.
        OutputMesh mesh = strip(1.0, 0.5);
        test::addUprightNeedle(mesh, 4.25, 0.25, 3);
        EditableSoup soup(mesh);
        QCOMPARE(soupIntersections(soup).size(), std::size_t(1));
        const int removed = spaceLineVertices(soup);
        qInfo("  %d line vertices removed, the others kept off the needle", removed);
        QCOMPARE(soupIntersections(soup).size(), std::size_t(1));
    }

    void linesAsSparseAsTheSurfacesStay()
    {
        EditableSoup soup(strip(1.0, 1.0));
        const int triangles = soup.result().triangles.size();
        QCOMPARE(spaceLineVertices(soup), 0);
        QCOMPARE(static_cast<int>(soup.result().triangles.size()), triangles);
    }
};

QTEST_APPLESS_MAIN(TestLineSpacing)
#include "test_line_spacing.moc"
