// A row of vertices down the middle of strips of tall triangles (remesh/strip_rows.h), on a flat
// strip between two contacts built in code: the strip is one rung wide, its lines as dense as the
// surfaces on either side, so that thinning the lines (line_spacing.h) cannot mend it.
#include "remesh/strip_rows.h"

#include "flat_soup_shape.h"
#include "model/model.h"
#include "remesh/intersection_repair.h"

#include <QtTest>

#include <vector>

using namespace stratamesh;

namespace {

std::vector<int> addRow(OutputMesh &m, double y, double step, std::vector<int> surfaces,
                        std::vector<int> lines)
{
    std::vector<int> ids;
    for (int k = 0; k * step <= 8.0 + 1e-9; ++k) {
        OutputPoint p;
        p.position = Vec3(k * step, y, 0.0);
        p.origin = lines.empty() ? PointOrigin::Surface : PointOrigin::Line;
        p.surfaces = surfaces;
        p.lines = lines;
        m.points.push_back(p);
        ids.push_back(static_cast<int>(m.points.size()) - 1);
    }
    return ids;
}

// Right triangles between two rows with the same x positions, normals +z.
void ladder(OutputMesh &m, const std::vector<int> &low, const std::vector<int> &high, int surface)
{
    for (std::size_t i = 0; i + 1 < low.size(); ++i) {
        m.triangles.push_back({{low[i], low[i + 1], high[i]}, surface});
        m.triangles.push_back({{low[i + 1], high[i + 1], high[i]}, surface});
    }
}

// Surfaces 1 (y ∈ [-0.5, 0]), 0 (the strip, y ∈ [0, width]) and 2 (y ∈ [width, width + 0.5]),
// 8 long, every row of vertices 0.5 apart: the strip triangles are 0.5 × width right triangles.
OutputMesh strip(double width)
{
    OutputMesh m;
    const auto c = addRow(m, -0.5, 0.5, {1}, {});
    const auto a = addRow(m, 0.0, 0.5, {0, 1}, {0});
    const auto b = addRow(m, width, 0.5, {0, 2}, {1});
    const auto d = addRow(m, width + 0.5, 0.5, {2}, {});
    ladder(m, c, a, 1);
    ladder(m, a, b, 0);
    ladder(m, b, d, 2);
    return m;
}

Surface rectangle(double y0, double y1)
{
    Surface s;
    s.vertices = {{0.0, y0, 0.0}, {8.0, y0, 0.0}, {8.0, y1, 0.0}, {0.0, y1, 0.0}};
    s.triangles = {{0, 1, 2}, {0, 2, 3}};
    return s;
}

// The input the soup samples: the three rectangles and the two lines between them.
Model input(double width)
{
    Model m;
    m.surfaces = {rectangle(0.0, width), rectangle(-0.5, 0.0), rectangle(width, width + 0.5)};
    m.vertices = {{0.0, 0.0, 0.0}, {8.0, 0.0, 0.0}, {0.0, width, 0.0}, {8.0, width, 0.0}};
    Line low, high;
    low.vertices = {0, 1};
    low.surfaces = {0, 1};
    high.vertices = {2, 3};
    high.surfaces = {0, 2};
    m.lines = {low, high};
    return m;
}

struct Shape {
    test::FlatSoupShape flat;
    int featureEdges = 0;
};

Shape shapeOf(const EditableSoup &soup)
{
    Shape s{test::flatSoupShape(soup)};
    for (int v = 0; v < soup.pointCount(); ++v)
        for (int w : soup.neighbours(v))
            s.featureEdges += v < w && soup.isFeatureEdge(v, w) ? 1 : 0;
    return s;
}

} // namespace

class TestStripRows : public QObject {
    Q_OBJECT

private slots:
    void aStripOfTallTrianglesGetsARowDownItsMiddle()
    {
        const Model model = input(1.0);
        InputProjector projector(model);
        EditableSoup soup(strip(1.0));
        const Shape before = shapeOf(soup);
        QCOMPARE(before.flat.small, 32); // the strip's 0.5 × 1 right triangles: 26.6°
        const int added = addStripRows(soup, projector);
        const Shape after = shapeOf(soup);
        qInfo("  %d vertices added, triangles under 30°: %d → %d", added, before.flat.small,
              after.flat.small);
        QVERIFY(added >= 8);
        QVERIFY(after.flat.small <= before.flat.small / 4);
        QCOMPARE(after.flat.flipped, 0);
        QCOMPARE(after.flat.offPlane, 0.0);
        // Same surfaces, same area each, and the contacts and borders untouched.
        QCOMPARE(after.flat.area.size(), std::size_t(3));
        for (const auto &[surface, area] : before.flat.area)
            QVERIFY(std::abs(after.flat.area.at(surface) - area) < 1e-9);
        QCOMPARE(after.featureEdges, before.featureEdges);
    }

    void aCrossingAlreadyThereDoesNotUndoTheRows()
    {
        // The rows are undone when they add crossings; one the soup had before is not theirs.
        const Model model = input(1.0);
        InputProjector projector(model);
        OutputMesh mesh = strip(1.0);
        test::addUprightNeedle(mesh, 4.25, -0.4, 3);
        EditableSoup soup(mesh);
        QCOMPARE(soupIntersections(soup).size(), std::size_t(1));
        const int before = shapeOf(soup).flat.small;
        const int added = addStripRows(soup, projector);
        qInfo("  %d vertices added beside a crossing, triangles under 30°: %d → %d", added, before,
              shapeOf(soup).flat.small);
        QVERIFY(added >= 8);
        QVERIFY(shapeOf(soup).flat.small <= before / 4);
        QCOMPARE(soupIntersections(soup).size(), std::size_t(1));
    }

    void aStripWideEnoughStays()
    {
        // 0.5 × 0.5 right triangles: 45°, nothing to mend.
        const Model model = input(0.5);
        InputProjector projector(model);
        EditableSoup soup(strip(0.5));
        const int triangles = static_cast<int>(soup.result().triangles.size());
        QCOMPARE(addStripRows(soup, projector), 0);
        QCOMPARE(static_cast<int>(soup.result().triangles.size()), triangles);
    }
};

QTEST_APPLESS_MAIN(TestStripRows)
#include "test_strip_rows.moc"
