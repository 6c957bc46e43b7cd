// The sizing field from the local feature size (feature_sizing.h) on boxes built in code, where the
// distance between the features is known from the construction: a fault throw of t puts the two
// cut-off lines of a horizon t apart along a vertical fault.
#include "common/error.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "remesh/feature_sizing.h"
#include "remesh/surface_remesher.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

Model faultedBox(double faultThrow, int horizons = 1)
{
    LayeredBoxParams bp;
    bp.size = Vec3(1000, 600, 400);
    bp.horizons = horizons;
    bp.fault = faultThrow > 0.0;
    bp.faultThrow = faultThrow;
    bp.edgeLength = 40;
    return recoverTopology(layeredBox(bp));
}

bool hasType(const Model &m, const Line &l, FeatureType type)
{
    for (int s : l.surfaces)
        if (m.surfaces[s].type == type)
            return true;
    return false;
}

// Vertices of the horizon–fault cut-off lines farther than `margin` from every corner.
std::vector<int> cutOffVertices(const Model &m, double margin)
{
    std::vector<int> out;
    for (const Line &l : m.lines) {
        if (!hasType(m, l, FeatureType::Horizon) || !hasType(m, l, FeatureType::Fault))
            continue;
        for (int v : l.vertices) {
            bool far = true;
            for (const Corner &c : m.corners)
                far = far && (m.vertices[v] - m.vertices[c.vertex]).norm() > margin;
            if (far)
                out.push_back(v);
        }
    }
    return out;
}

FeatureSizingParams sizingParams(double edge)
{
    FeatureSizingParams p;
    p.edgeLength = edge;
    p.minEdgeLength = edge / 64.0;
    return p;
}

} // namespace

class TestFeatureSizing : public QObject {
    Q_OBJECT
private slots:
    // The two cut-off lines of a 15 m throw are 15 m apart: that is their local feature size,
    // and the size there is κ times it.
    void cutOffLinesOfASmallThrowAreTheirThrowApart()
    {
        const Model m = faultedBox(15);
        FeatureSizingParams p = sizingParams(100);
        p.lfsFactor = 0.8;
        const FeatureSizing s = computeFeatureSizing(m, p);
        const std::vector<int> vertices = cutOffVertices(m, 40);
        QVERIFY(vertices.size() >= 20);
        for (int v : vertices) {
            QVERIFY2(std::abs(s.lfs[v] - 15.0) < 0.5, qPrintable(QString::number(s.lfs[v])));
            QVERIFY2(std::abs(s.size[v] - 12.0) < 0.5, qPrintable(QString::number(s.size[v])));
        }
        QVERIFY(s.siteFactor > 1.2);
        QVERIFY(s.refinedVertices > 0);
        QVERIFY(std::abs(s.smallestLfs - 15.0) < 0.5 || s.smallestLfs < 15.0);
    }

    // A throw wider than the edge length is nothing to refine: no vertex is within reach of a
    // feature it does not meet (the horizon is 200 m from the box's top and bottom lines).
    void featuresFartherThanTheEdgeLengthChangeNothing()
    {
        const Model m = faultedBox(150);
        const FeatureSizing s = computeFeatureSizing(m, sizingParams(100));
        for (int v : cutOffVertices(m, 40))
            QVERIFY2(!std::isfinite(s.lfs[v]) || s.lfs[v] >= 100.0,
                     qPrintable(QString::number(s.lfs[v])));
        QCOMPARE(s.refinedVertices, 0);
        QCOMPARE(s.siteFactor, 1.0);
        for (double h : s.size)
            QCOMPARE(h, 100.0);
    }

    // h(p) ≤ h(q) + g·|p − q| for every pair of vertices, and h = h0 beyond the reach of the
    // refined ones.
    void theFieldIsGraded()
    {
        const Model m = faultedBox(10);
        FeatureSizingParams p = sizingParams(120);
        p.gradation = 0.3;
        const FeatureSizing s = computeFeatureSizing(m, p);
        QVERIFY(s.refinedVertices > 0);
        const std::size_t n = m.vertices.size();
        double worst = 0.0;
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = 0; b < n; ++b)
                worst = std::max(worst, s.size[a] - s.size[b]
                                            - p.gradation * (m.vertices[a] - m.vertices[b]).norm());
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
        double smallest = p.edgeLength;
        for (double h : s.size) {
            QVERIFY(h >= p.minEdgeLength - 1e-12 && h <= p.edgeLength);
            smallest = std::min(smallest, h);
        }
        for (std::size_t a = 0; a < n; ++a) {
            bool reached = false;
            for (std::size_t b = 0; b < n && !reached; ++b)
                reached = s.size[b] < p.edgeLength
                          && (m.vertices[a] - m.vertices[b]).norm()
                                 < (p.edgeLength - smallest) / p.gradation;
            if (!reached)
                QCOMPARE(s.size[a], p.edgeLength);
        }
    }

    // Features closer than d_resolution are the merge's: they keep cells of the edge length.
    void featuresBelowDResolutionAreNotRefined()
    {
        const Model m = faultedBox(15);
        FeatureSizingParams p = sizingParams(100);
        p.dResolution = 20;
        const FeatureSizing s = computeFeatureSizing(m, p);
        const FeatureSizing all = computeFeatureSizing(m, sizingParams(100));
        // Not refined for themselves; grading from the features above D may still reach them.
        for (int v : cutOffVertices(m, 40)) {
            QVERIFY(s.lfs[v] < 20.0);
            QVERIFY2(s.size[v] >= 20.0, qPrintable(QString::number(s.size[v])));
            QVERIFY(all.size[v] < 20.0);
        }
        QVERIFY(s.siteFactor < all.siteFactor);
    }

    // Lines meeting at a corner at a wide angle (90° at the box corners) are not close features.
    void linesMeetingAtACornerAreNotCloseFeatures()
    {
        const Model m = faultedBox(0, 2);
        const FeatureSizing s = computeFeatureSizing(m, sizingParams(60));
        for (const Corner &c : m.corners)
            QCOMPARE(s.size[c.vertex], 60.0);
        QCOMPARE(s.refinedVertices, 0);
    }

    // The density the CVT gets spaces sites as h: ρ = (h0 / h)⁴.
    void densityIsTheFourthPowerOfTheSizeRatio()
    {
        const Model m = faultedBox(15);
        const FeatureSizing s = computeFeatureSizing(m, sizingParams(100));
        const std::vector<double> rho = sizingDensity(s, 100);
        QCOMPARE(rho.size(), m.vertices.size());
        for (std::size_t v = 0; v < rho.size(); ++v)
            QVERIFY(std::abs(rho[v] - std::pow(100.0 / s.size[v], 4)) <= 1e-9 * rho[v]);
    }

    // A remesh of a 15 m throw at a 60 m edge length, thin strip kept and no refinement rounds
    // after the fact: the uniform sites leave the strip between the cut-off lines to needles and
    // the ledger records topology changes there; the sized sites keep every line and corner, at
    // more sites.
    void sizedRemeshKeepsTheTopologyOfASmallThrow()
    {
        const Model m = faultedBox(15, 2);
        RemeshParams p;
        p.edgeLength = 60;
        p.stripWidthFactor = 0.0;
        p.lfsFactor = 0.0;
        p.refinementRounds = 0;
        const RemeshResult uniform = remeshModel(m, p);
        p.lfsFactor = 1.0;
        const RemeshResult sized = remeshModel(m, p);
        const int uniformEdits = countTopologyEdits(uniform.ledger).total();
        const int sizedEdits = countTopologyEdits(sized.ledger).total();
        qInfo("edits uniform %d (%d sites), sized %d (%d sites, %d sized)", uniformEdits,
              uniform.siteCount, sizedEdits, sized.siteCount, sized.sizedSiteCount);
        QVERIFY(sized.validity.valid);
        QVERIFY(sized.sizedSiteCount > sized.initialSiteCount);
        QVERIFY(sized.smallestCellSize < 60.0);
        QVERIFY(uniformEdits > 0);
        QCOMPARE(sizedEdits, 0);
    }

    void badInputIsRefused()
    {
        QVERIFY_THROWS_EXCEPTION(InputError, computeFeatureSizing(faultedBox(15), sizingParams(0)));
        LayeredBoxParams bp;
        QVERIFY_THROWS_EXCEPTION(InputError,
                                 computeFeatureSizing(layeredBox(bp), sizingParams(50)));
    }
};

QTEST_APPLESS_MAIN(TestFeatureSizing)
#include "test_feature_sizing.moc"
