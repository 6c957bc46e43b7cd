// Topology recovery: exact merge across surfaces only, line and corner definitions, incidences.
#include "hand_models.h"

#include "common/error.h"
#include "model/model_counts.h"
#include "model/surface_edges.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/unused_vertices.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <map>
#include <set>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

EntityCounts counts(int r, int s, int l, int c)
{
    return {r, s, l, c};
}

QString text(const EntityCounts &c)
{
    return QStringLiteral("%1/%2/%3/%4").arg(c.regions).arg(c.surfaces).arg(c.lines).arg(c.corners);
}

int lineWithSurfaces(const Model &m, std::vector<int> surfaces)
{
    for (std::size_t l = 0; l < m.lines.size(); ++l)
        if (m.lines[l].surfaces == surfaces)
            return static_cast<int>(l);
    return -1;
}

// Properties every recovered topology must have, whatever the model.
void checkConsistency(const Model &m)
{
    QVERIFY(m.hasTopology());
    // Global vertices are unique points and the local→global map keeps positions.
    std::set<std::array<double, 3>> seen;
    for (const Vec3 &p : m.vertices)
        QVERIFY(seen.insert({p.x(), p.y(), p.z()}).second);
    for (std::size_t s = 0; s < m.surfaces.size(); ++s)
        for (std::size_t v = 0; v < m.surfaces[s].vertices.size(); ++v)
            QCOMPARE(m.vertices[m.surfaceVertexToGlobal[s][v]], m.surfaces[s].vertices[v]);

    // Which surfaces hold each global edge, and which edges are on a surface border.
    std::map<long long, std::set<int>> holders;
    std::set<long long> border;
    for (const SurfaceEdge &e : surfaceEdges(m)) {
        holders[e.key].insert(e.surface);
        if (e.triangles == 1)
            border.insert(e.key);
    }
    std::map<long long, int> lineOfEdge;
    for (std::size_t l = 0; l < m.lines.size(); ++l) {
        const Line &line = m.lines[l];
        QVERIFY(std::is_sorted(line.surfaces.begin(), line.surfaces.end()));
        const std::size_t n = line.vertices.size();
        QVERIFY(n >= 2);
        for (std::size_t i = 0; i < (line.closed ? n : n - 1); ++i) {
            const long long key = edgeKey(line.vertices[i], line.vertices[(i + 1) % n]);
            QVERIFY2(lineOfEdge.emplace(key, static_cast<int>(l)).second, "an edge in two lines");
            const std::set<int> &h = holders[key];
            QCOMPARE(std::vector<int>(h.begin(), h.end()), line.surfaces);
        }
        if (line.closed) {
            QCOMPARE(line.corners[0], -1);
        } else {
            QCOMPARE(m.corners[line.corners[0]].vertex, line.vertices.front());
            QCOMPARE(m.corners[line.corners[1]].vertex, line.vertices.back());
        }
        for (int s : line.surfaces) {
            const std::vector<int> &sl = m.surfaces[s].lines;
            QVERIFY(std::find(sl.begin(), sl.end(), static_cast<int>(l)) != sl.end());
        }
    }
    // Every border edge and every edge shared by two surfaces is on exactly one line.
    for (const auto &[key, h] : holders)
        if (border.count(key) || h.size() >= 2)
            QVERIFY2(lineOfEdge.count(key), "a contact or border edge is on no line");
    for (std::size_t c = 0; c < m.corners.size(); ++c)
        for (int l : m.corners[c].lines)
            QVERIFY(m.lines[l].corners[0] == static_cast<int>(c)
                    || m.lines[l].corners[1] == static_cast<int>(c));
    for (std::size_t r = 0; r < m.regions.size(); ++r)
        for (const RegionSide &side : m.regions[r].boundaries) {
            const std::vector<int> &sr = m.surfaces[side.surface].regions;
            QVERIFY(std::find(sr.begin(), sr.end(), static_cast<int>(r)) != sr.end());
        }
}

} // namespace

class TestTopology : public QObject {
    Q_OBJECT

private slots:
    void lonelySquareHasOneClosedLine()
    {
        const Model m = recoverTopology(modelOf({square("a")}));
        QCOMPARE(m.vertices.size(), std::size_t(4));
        QCOMPARE(m.lines.size(), std::size_t(1));
        QVERIFY(m.lines[0].closed);
        QCOMPARE(m.lines[0].vertices.size(), std::size_t(4));
        QCOMPARE(m.corners.size(), std::size_t(0));
        QCOMPARE(m.surfaces[0].lines, std::vector<int>{0});
        QCOMPARE(m.lines[0].name, std::string("line_0"));
        checkConsistency(m);
    }

    // A vertex left by a re-triangulation goes; the others keep their order and positions.
    void unusedVerticesAreDropped()
    {
        Surface s = makeSurface("s", {{0, 0, 0}, {1, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}, {0, 1, 0}},
                                {{0, 1, 3}, {0, 3, 4}});
        const Model before = recoverTopology(modelOf({s}));
        QCOMPARE(before.vertices.size(), std::size_t(5)); // the free centre is a global point
        QCOMPARE(dropUnusedVertices(s), 1);
        QCOMPARE(s.vertices.size(), std::size_t(4));
        QCOMPARE(s.vertices[2], Vec3(1, 1, 0));
        QCOMPARE(s.triangles[0], (Triangle{0, 1, 2}));
        QCOMPARE(s.triangles[1], (Triangle{0, 2, 3}));
        QCOMPARE(dropUnusedVertices(s), 0);
        const Model after = recoverTopology(modelOf({s}));
        QCOMPARE(after.vertices.size(), std::size_t(4));
        QCOMPARE(after.lines.size(), std::size_t(1));
        checkConsistency(after);
    }

    // Two local vertices at one position share a global id but never connect the triangles:
    // the diagonal is a cut (an internal line), ending at two corners.
    void duplicatesInsideOneSurfaceAreNotMerged()
    {
        const Surface cut =
            makeSurface("cut", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                        {{0, 1, 2}, {3, 4, 5}});
        const Model m = recoverTopology(modelOf({cut}));
        QCOMPARE(m.vertices.size(), std::size_t(4));
        QCOMPARE(m.surfaceVertexToGlobal[0][3], m.surfaceVertexToGlobal[0][0]);
        QCOMPARE(m.corners.size(), std::size_t(2));
        QCOMPARE(m.lines.size(), std::size_t(3)); // the diagonal and the two halves of the border
        int diagonals = 0;
        for (const Line &l : m.lines)
            diagonals += l.vertices.size() == 2 ? 1 : 0;
        QCOMPARE(diagonals, 1);
        checkConsistency(m);
    }

    void twoSquaresSharingAnEdge()
    {
        Surface b = square("b");
        for (Vec3 &p : b.vertices)
            p.x() += 1.0;
        const Model m = recoverTopology(modelOf({square("a"), b}));
        QCOMPARE(m.vertices.size(), std::size_t(6));
        QCOMPARE(m.corners.size(), std::size_t(2));
        QCOMPARE(m.lines.size(), std::size_t(3));
        QVERIFY(lineWithSurfaces(m, {0, 1}) >= 0);
        QCOMPARE(m.lines[lineWithSurfaces(m, {0, 1})].vertices.size(), std::size_t(2));
        for (const Corner &c : m.corners) {
            QCOMPARE(m.vertices[c.vertex].x(), 1.0);
            QCOMPARE(c.lines.size(), std::size_t(3));
        }
        checkConsistency(m);
    }

    // A fault standing on a horizon without cutting it: the contact edges are interior to the
    // horizon, yet they make a line (shared by two surfaces), internal to the horizon.
    void faultEndingOnAnUncutHorizon()
    {
        Surface h = makeSurface("h", {}, {});
        for (int j = 0; j <= 2; ++j)
            for (int i = 0; i <= 2; ++i)
                h.vertices.push_back({double(i), double(j), 0.0});
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const int a = j * 3 + i;
                h.triangles.push_back({a, a + 1, a + 4});
                h.triangles.push_back({a, a + 4, a + 3});
            }
        Surface f =
            makeSurface("f", {{1, 0, 0}, {1, 1, 0}, {1, 2, 0}, {1, 0, 1}, {1, 1, 1}, {1, 2, 1}},
                        {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}}, FeatureType::Fault);
        const Model m = recoverTopology(modelOf({h, f}));
        QCOMPARE(m.vertices.size(), std::size_t(12));
        QCOMPARE(m.corners.size(),
                 std::size_t(2)); // where the fault's foot meets the horizon border
        QCOMPARE(m.lines.size(),
                 std::size_t(4)); // contact, fault border, two horizon border halves
        const int contact = lineWithSurfaces(m, {0, 1});
        QVERIFY(contact >= 0);
        QCOMPARE(m.lines[contact].vertices.size(), std::size_t(3));
        QCOMPARE(m.surfaces[0].lines.size(), std::size_t(3)); // incl. the internal contact line
        QCOMPARE(m.surfaces[1].lines.size(), std::size_t(2));
        checkConsistency(m);
    }

    // A small fault whose foot is inside the horizon: at each end of the foot two line edges
    // meet whose incident surfaces differ ({h, f} then {f}), which makes a corner.
    void incidenceChangeMakesACorner()
    {
        Surface h = makeSurface("h", {}, {});
        for (int j = 0; j <= 3; ++j)
            for (int i = 0; i <= 3; ++i)
                h.vertices.push_back({double(i), double(j), 0.0});
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const int a = j * 4 + i;
                h.triangles.push_back({a, a + 1, a + 5});
                h.triangles.push_back({a, a + 5, a + 4});
            }
        const Surface f = makeSurface("f", {{1, 1, 0}, {1, 2, 0}, {1, 1, 1}, {1, 2, 1}},
                                      {{0, 1, 3}, {0, 3, 2}}, FeatureType::Fault);
        const Model m = recoverTopology(modelOf({h, f}));
        QCOMPARE(m.corners.size(), std::size_t(2));
        for (const Corner &c : m.corners) {
            QCOMPARE(m.vertices[c.vertex].z(), 0.0);
            QCOMPARE(c.lines.size(), std::size_t(2));
        }
        QCOMPARE(m.lines.size(),
                 std::size_t(3)); // horizon border (closed), fault foot, rest of the fault border
        const int border = lineWithSurfaces(m, {0});
        QVERIFY(border >= 0 && m.lines[border].closed);
        QCOMPARE(m.lines[border].vertices.size(), std::size_t(12));
        QCOMPARE(m.lines[lineWithSurfaces(m, {0, 1})].vertices.size(), std::size_t(2));
        QCOMPARE(m.lines[lineWithSurfaces(m, {1})].vertices.size(), std::size_t(4));
        checkConsistency(m);
    }

    // Box cut by one horizon: 10 box patches (top, bottom, 2 per side) + the horizon; lines:
    // 4 horizon borders + 4 bottom and 4 top cube edges + 8 half vertical edges = 20;
    // corners: 8 cube corners + 4 where the horizon meets the vertical edges = 12.
    void boxCutByOneHorizon()
    {
        LayeredBoxParams p;
        p.horizons = 1;
        p.foldAmplitude = 60.0;
        const Model m = recoverTopology(layeredBox(p));
        const ModelCounts c = countEntities(m);
        QCOMPARE(text(c.all), text(counts(2, 11, 20, 12)));
        QCOMPARE(text(c.withoutBox), text(counts(2, 1, 0, 0)));
        checkConsistency(m);
    }

    // N horizons, no fault: surfaces 2 + 4(N+1) + N, lines 8N + 12, corners 8 + 4N.
    void boxCutByThreeHorizons()
    {
        LayeredBoxParams p;
        p.horizons = 3;
        const ModelCounts c = countEntities(recoverTopology(layeredBox(p)));
        QCOMPARE(text(c.all), text(counts(4, 2 + 16 + 3, 8 * 3 + 12, 8 + 12)));
        QCOMPARE(text(c.withoutBox), text(counts(4, 3, 0, 0)));
    }

    // One horizon offset by a vertical fault. Surfaces: 8 box patches per block, 2 horizon
    // patches, 3 fault patches (cut at both cutoffs). Lines: 16 in the west block (incl. the
    // fault foot and head), 14 in the east block, 3 fault traces on each of the south and north
    // faces = 36, of which the two cutoff lines are inside the box. Corners: 8 cube corners,
    // 4 horizon/vertical-edge, 4 fault/box-edge, 4 cutoff ends = 20, all on the box.
    void boxWithVerticalFaultAndThrow()
    {
        LayeredBoxParams p;
        p.horizons = 1;
        p.fault = true;
        p.faultThrow = 50.0;
        const Model m = recoverTopology(layeredBox(p));
        const ModelCounts c = countEntities(m);
        QCOMPARE(text(c.all), text(counts(4, 21, 36, 20)));
        QCOMPARE(text(c.withoutBox), text(counts(4, 5, 2, 0)));
        QVERIFY(lineWithSurfaces(m, {}) < 0);
        checkConsistency(m);
    }

    // Without throw both horizon patches meet the fault on one line shared by four surfaces.
    void faultWithoutThrowSharesOneCutoffLine()
    {
        LayeredBoxParams p;
        p.horizons = 1;
        p.fault = true;
        p.faultDipDegrees = 70.0;
        const Model m = recoverTopology(layeredBox(p));
        const ModelCounts c = countEntities(m);
        QCOMPARE(text(c.all), text(counts(4, 20, 33, 18)));
        QCOMPARE(text(c.withoutBox), text(counts(4, 4, 1, 0)));
        int fourWay = 0;
        for (const Line &l : m.lines)
            fourWay += l.surfaces.size() == 4 ? 1 : 0;
        QCOMPARE(fourWay, 1);
        checkConsistency(m);
    }

    void nestedSpheresHaveNoLines()
    {
        const Model m = recoverTopology(nestedSpheres({}));
        const ModelCounts c = countEntities(m);
        QCOMPARE(text(c.all), text(counts(2, 2, 0, 0)));
        QCOMPARE(text(c.withoutBox), text(counts(2, 1, 0, 0)));
        QCOMPARE(m.surfaces[0].regions, (std::vector<int>{0, 1}));
        QCOMPARE(m.surfaces[1].regions, std::vector<int>{1});
    }

    void sampleModelIsConsistentAndIdempotent()
    {
        const Model once = recoverTopology(sampleModel());
        checkConsistency(once);
        const Model twice = recoverTopology(once);
        QCOMPARE(twice.vertices.size(), once.vertices.size());
        QCOMPARE(twice.lines.size(), once.lines.size());
        QCOMPARE(twice.corners.size(), once.corners.size());
        QCOMPARE(twice.surfaces[0].lines, once.surfaces[0].lines);
    }

    void badInputIsRejected()
    {
        Model outOfRange =
            modelOf({makeSurface("bad", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}})});
        QVERIFY_THROWS_EXCEPTION(InputError, recoverTopology(outOfRange));
        Model nan = modelOf({square("nan")});
        nan.surfaces[0].vertices[2].z() = std::numeric_limits<double>::quiet_NaN();
        QVERIFY_THROWS_EXCEPTION(InputError, recoverTopology(nan));
        Model badSide = modelOf({square("a")});
        badSide.regions.push_back({"r", {{3, true}}});
        QVERIFY_THROWS_EXCEPTION(InputError, recoverTopology(badSide));
    }

    void negativeZeroMergesWithZero()
    {
        Surface b = square("b");
        for (Vec3 &p : b.vertices) {
            p.x() += 1.0;
            p.z() = -0.0;
        }
        const Model m = recoverTopology(modelOf({square("a"), b}));
        QCOMPARE(m.vertices.size(), std::size_t(6));
    }
};

QTEST_GUILESS_MAIN(TestTopology)
#include "test_topology.moc"
