// The remesher on models built in code (thesis ch. 4): topology of the output, borders, lines,
// corners and contacts, and the d_resolution simplification (Fig 4.3, 4.5, 4.7).
#include "remesh/surface_remesher.h"

#include "common/error.h"
#include "model/model_counts.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/validity.h"
#include "remesh/output_model_builder.h"
#include "support/model_lines.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <cmath>
#include <limits>
#include <map>
#include <set>

using namespace stratamesh;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Euler characteristic V − E + F of one surface (local ids).
int eulerCharacteristic(const Surface &s)
{
    std::set<std::pair<int, int>> edges;
    std::set<int> vertices;
    for (const Triangle &t : s.triangles)
        for (int k = 0; k < 3; ++k) {
            vertices.insert(t[k]);
            edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
        }
    return static_cast<int>(vertices.size()) - static_cast<int>(edges.size())
           + static_cast<int>(s.triangles.size());
}

// Edge → number of triangles of the surface around it.
std::map<std::pair<int, int>, int> edgeUse(const Surface &s)
{
    std::map<std::pair<int, int>, int> use;
    for (const Triangle &t : s.triangles)
        for (int k = 0; k < 3; ++k)
            ++use[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    return use;
}

int borderEdgeCount(const Surface &s)
{
    int n = 0;
    for (const auto &[e, count] : edgeUse(s))
        n += count == 1 ? 1 : 0;
    return n;
}

double area(const Surface &s)
{
    double a = 0;
    for (const Triangle &t : s.triangles)
        a += 0.5
             * (s.vertices[t[1]] - s.vertices[t[0]])
                   .cross(s.vertices[t[2]] - s.vertices[t[0]])
                   .norm();
    return a;
}

// A flat square [0, n·h]² at z = 0, optionally with a square hole in its middle.
Model squareModel(int n, double h, bool hole)
{
    Surface s;
    s.name = hole ? "holed" : "square";
    s.featureName = s.name;
    s.type = FeatureType::Horizon;
    std::map<std::pair<int, int>, int> id;
    auto vertex = [&](int i, int j) {
        auto [it, inserted] = id.emplace(std::make_pair(i, j), static_cast<int>(s.vertices.size()));
        if (inserted)
            s.vertices.push_back(Vec3(i * h, j * h, 0.0));
        return it->second;
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (hole && i >= n / 3 && i < n - n / 3 && j >= n / 3 && j < n - n / 3)
                continue;
            s.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
            s.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
        }
    Model m;
    m.name = s.name;
    m.surfaces.push_back(s);
    return recoverTopology(m);
}

const Surface *surfaceNamed(const Model &m, const std::string &name)
{
    for (const Surface &s : m.surfaces)
        if (s.name == name)
            return &s;
    return nullptr;
}

bool mentions(const LedgerRecord &r, FeatureType type, const Model &input)
{
    for (const EntityRef &e : r.inputs)
        if (e.kind == EntityKind::Surface && input.surfaces[e.id].type == type)
            return true;
    return false;
}

} // namespace

class TestSurfaceRemesher : public QObject {
    Q_OBJECT
private slots:
    void surfacePartsLargestFirst()
    {
        // A split surface is reviewed part by part: where each extra piece is, and how big.
        Surface s;
        s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 0}, {9, 5, 0}, {5, 9, 0}, {9, 9, 0}};
        s.triangles = {{0, 1, 2}, {3, 4, 5}, {4, 6, 5}};
        const std::vector<SurfacePart> parts = surfaceParts(s);
        QCOMPARE(static_cast<int>(parts.size()), 2);
        QCOMPARE(surfaceComponentCount(s), 2);
        QCOMPARE(parts[0].triangles, 2);
        QVERIFY(std::abs(parts[0].area - 16.0) < 1e-12);
        QVERIFY((parts[0].centroid - Vec3(7, 7, 0)).norm() < 1e-12);
        QVERIFY(std::abs(parts[1].area - 0.5) < 1e-12);
        QVERIFY((parts[1].centroid - Vec3(1.0 / 3, 1.0 / 3, 0)).norm() < 1e-12);
    }

    void nestedSpheresGiveTwoSpheres()
    {
        // Fig 4.3: 100 sites sandwiched between two close spheres; each cell has two components.
        NestedSpheresParams sp;
        sp.innerRadius = 1.0;
        sp.outerRadius = 1.12;
        sp.subdivisions = 4;
        const Model input = recoverTopology(nestedSpheres(sp));
        RemeshParams params;
        params.sites = 100;
        params.iterations = 30;
        const RemeshResult r = remeshModel(input, params);
        QCOMPARE(r.model.surfaces.size(), std::size_t(2));
        for (const Surface &s : r.model.surfaces) {
            QCOMPARE(eulerCharacteristic(s), 2);
            for (const auto &[e, count] : edgeUse(s))
                QCOMPARE(count, 2); // closed, manifold
            QVERIFY(s.vertices.size() >= 60);
        }
        QVERIFY(checkValidity(r.model).valid);
    }

    void squareKeepsItsBorder()
    {
        const Model input = squareModel(20, 0.5, false); // 10 × 10
        RemeshParams params;
        params.sites = 150;
        params.iterations = 40;
        const RemeshResult r = remeshModel(input, params);
        QCOMPARE(r.model.surfaces.size(), std::size_t(1));
        const Surface &s = r.model.surfaces[0];
        QCOMPARE(eulerCharacteristic(s), 1); // a disc
        QVERIFY(std::abs(area(s) - 100.0) < 1.0);
        QVERIFY(borderEdgeCount(s) >= 20);
        // Border vertices lie on the square's border.
        for (const auto &[e, count] : edgeUse(s))
            if (count == 1)
                for (int v : {e.first, e.second}) {
                    const Vec3 &p = s.vertices[v];
                    const double d = std::min({p.x(), 10.0 - p.x(), p.y(), 10.0 - p.y()});
                    QVERIFY2(std::abs(d) < 1e-9,
                             qPrintable(
                                 QStringLiteral("border vertex off the input border: %1 %2 %3 d=%4")
                                     .arg(p.x())
                                     .arg(p.y())
                                     .arg(p.z())
                                     .arg(d)));
                }
        QCOMPARE(r.model.lines.size(), input.lines.size());
        // A lone square is open like its input (not sealed); everything else must be clean.
        const ValidityReport v = checkValidity(r.model);
        QCOMPARE(v.counts.size(), checkValidity(input).counts.size());
        QCOMPARE(v.count(validity_check::notSealed), std::size_t(1));
    }

    void holeIsKept()
    {
        const Model input = squareModel(24, 0.5, true); // hole of 4 × 4 in a 12 × 12 square
        RemeshParams params;
        params.sites = 300;
        params.iterations = 40;
        const RemeshResult r = remeshModel(input, params);
        QCOMPARE(r.model.surfaces.size(), std::size_t(1));
        QCOMPARE(eulerCharacteristic(r.model.surfaces[0]), 0); // an annulus
        QCOMPARE(r.model.lines.size(), std::size_t(2));
        QCOMPARE(countKind(r.ledger, LedgerKind::LineLost), 0);
    }

    void boxCutByOneHorizonStaysConformal()
    {
        LayeredBoxParams bp;
        bp.size = Vec3(1000, 600, 400);
        bp.horizons = 1;
        bp.edgeLength = 50;
        const Model input = recoverTopology(layeredBox(bp));
        RemeshParams params;
        params.edgeLength = 80;
        params.iterations = 40;
        const RemeshResult r = remeshModel(input, params);
        const ValidityReport v = checkValidity(r.model);
        QVERIFY2(v.valid, v.problems.empty() ? "" : v.problems.front().message.c_str());
        const ModelCounts in = countEntities(input), out = countEntities(r.model);
        QCOMPARE(out.all.surfaces, in.all.surfaces);
        QCOMPARE(out.all.lines, in.all.lines);
        QCOMPARE(out.all.corners, in.all.corners);
        QCOMPARE(out.all.regions, in.all.regions);
        // Every output surface keeps the name, feature and type of its input surface.
        for (const Surface &s : r.model.surfaces) {
            const Surface *i = surfaceNamed(input, s.name);
            QVERIFY(i);
            QCOMPARE(s.featureName, i->featureName);
            QVERIFY(s.type == i->type);
        }
    }

    void edgeLengthAndAdaptiveDensity()
    {
        LayeredBoxParams bp;
        bp.size = Vec3(1000, 600, 400);
        bp.horizons = 1;
        bp.edgeLength = 50;
        const Model input = recoverTopology(layeredBox(bp));
        QCOMPARE(sitesForEdgeLength(std::sqrt(3.0) / 2.0 * 100.0, 1.0), 100);
        QVERIFY_THROWS_EXCEPTION(InputError, sitesForEdgeLength(1.0, 0.0));
        // An edge length that overflowed int (modelA1 at 0.6 ran with 4 sites) is refused.
        QVERIFY_THROWS_EXCEPTION(InputError, sitesForEdgeLength(1e12, 0.6));
        QCOMPARE(sitesForEdgeLength(std::sqrt(3.0) / 2.0 * kMaxRemeshSites, 1.0), kMaxRemeshSites);

        // Parameters that make no sense for this model are refused before any work.
        RemeshParams tooFew;
        tooFew.sites = static_cast<int>(input.surfaces.size()) - 1;
        QVERIFY_THROWS_EXCEPTION(InputError, remeshModel(input, tooFew));
        RemeshParams tooCoarse;
        tooCoarse.sites = 500;
        tooCoarse.dResolution = 1000.0; // the box diagonal is about 1229
        QVERIFY_THROWS_EXCEPTION(InputError, remeshModel(input, tooCoarse));

        RemeshParams params;
        params.edgeLength = 100;
        params.iterations = 30;
        const RemeshResult uniform = remeshModel(input, params);
        double sum = 0;
        int edges = 0;
        for (const Surface &s : uniform.model.surfaces)
            for (const auto &[e, count] : edgeUse(s)) {
                sum += (s.vertices[e.first] - s.vertices[e.second]).norm();
                ++edges;
            }
        const double mean = sum / edges;
        QVERIFY2(mean > 75 && mean < 125, qPrintable(QString::number(mean)));

        // Thesis Fig 4.19: ρ = (1 − d/d_max)^4 from the corners puts the vertices near them.
        params.adaptive = true;
        const RemeshResult adaptive = remeshModel(input, params);
        QVERIFY(checkValidity(adaptive.model).valid);
        auto nearCorners = [&input](const Model &m) {
            int n = 0;
            for (const Vec3 &v : m.vertices) {
                double d = std::numeric_limits<double>::max();
                for (const Corner &c : input.corners)
                    d = std::min(d, (input.vertices[c.vertex] - v).norm());
                n += d < 150.0 ? 1 : 0;
            }
            return n;
        };
        QVERIFY2(nearCorners(adaptive.model) > 2 * nearCorners(uniform.model),
                 qPrintable(QStringLiteral("%1 vs %2")
                                .arg(nearCorners(adaptive.model))
                                .arg(nearCorners(uniform.model))));
    }

    void smallThrowCancelledByDResolution()
    {
        LayeredBoxParams bp;
        bp.size = Vec3(1000, 600, 400);
        bp.horizons = 1;
        bp.fault = true;
        bp.faultThrow = 15;
        bp.edgeLength = 40;
        const Model input = recoverTopology(layeredBox(bp));
        RemeshParams params;
        params.edgeLength = 90;
        params.iterations = 40;
        params.stripWidthFactor = 0; // d_resolution alone (test_thin_strips removes whole strips)

        // Lines along the fault that both fault blocks of the horizon share.
        auto joinedLines = [](const Model &m) {
            return test::countLines(
                m, [](int horizons, int faults) { return horizons >= 2 && faults >= 1; });
        };
        QCOMPARE(joinedLines(input), 0);

        // d_resolution = 0: both horizon contacts on the fault stay apart (the throw stays).
        params.dResolution = 0.0;
        const RemeshResult kept = remeshModel(input, params);
        QCOMPARE(countKind(kept.ledger, LedgerKind::CloseFeatureMerge), 0);
        QCOMPARE(joinedLines(kept.model), 0);

        // d_resolution above the throw: the two contacts merge, and the records say which surfaces.
        params.dResolution = 40.0;
        const RemeshResult merged = remeshModel(input, params);
        int namingBoth = 0;
        for (const LedgerRecord &rec : merged.ledger)
            if (rec.kind == LedgerKind::CloseFeatureMerge
                && mentions(rec, FeatureType::Fault, input)
                && mentions(rec, FeatureType::Horizon, input))
                ++namingBoth;
        QVERIFY(namingBoth > 0);
        QVERIFY(joinedLines(merged.model) > 0);

        // Cancelled means the fault strip between the two contacts is gone as a whole, and
        // said so; kept means it is still there. Both outputs stay valid.
        auto faultSurfaces = [](const Model &m) {
            int n = 0;
            for (const Surface &s : m.surfaces)
                n += s.type == FeatureType::Fault ? 1 : 0;
            return n;
        };
        QCOMPARE(faultSurfaces(input), 3);
        QCOMPARE(faultSurfaces(kept.model), 3);
        QCOMPARE(faultSurfaces(merged.model), 2);
        QVERIFY(countKind(merged.ledger, LedgerKind::SurfaceLost) >= 1);
        QVERIFY(checkValidity(kept.model).valid);
        QVERIFY(checkValidity(merged.model).valid);
    }

    // A fault network whose strips (throws of 6 to 50 m) are far narrower than the edges (about
    // 110 m at 400 sites): refinement rounds that pin sites on the features around each change
    // keep most of the topology the plain rounds lose, within the growth cap, and stay valid.
    void pinnedFeaturesKeepMoreOfTheTopology()
    {
        const Model input = recoverTopology(faultNetworkBox(3, 20, 2, 20, 60));
        RemeshParams params;
        params.sites = 400;
        params.stripWidthFactor = 0; // keep every strip
        const RemeshResult plain = remeshModel(input, params);
        params.refinementPinsFeatures = true;
        const RemeshResult pinned = remeshModel(input, params);
        const int before = countTopologyEdits(plain.ledger).total();
        const int after = countTopologyEdits(pinned.ledger).total();
        qInfo("network of 3 faults, 400 sites: %d topology edits with %d sites, %d with %d pinned",
              before, plain.siteCount, after, pinned.siteCount);
        QVERIFY(before >= 20);
        QVERIFY2(after * 4 <= before, qPrintable(QString("%1 → %2").arg(before).arg(after)));
        QVERIFY(pinned.siteCount <= static_cast<int>(params.sizingMaxGrowth * params.sites) + 500);
        QVERIFY(pinned.validity.valid);
        QVERIFY(checkValidity(pinned.model).valid);
    }

    // Rounds only add sites: after a valid round over the quality allowance no other round runs,
    // and that round is not kept; with room in the allowance the rounds go on. At 500 sites the
    // first round is valid (at 300 it folds a contact, and the second one is the first valid).
    // A valid start leaves a round over the allowance nothing to mend, so its validity is not
    // even checked.
    void refinementStopsOverTheQualityAllowance()
    {
        const Model input = recoverTopology(faultNetworkBox(1, 20, 2, 20, 60));
        RemeshParams params;
        params.sites = 500;
        params.refinementMaxQualityLoss = 100.0; // no round is over it
        std::set<std::string> stagesWithin, stagesOver;
        auto recorder = [](std::set<std::string> &stages) {
            return Progress([&stages](double, const std::string &stage) {
                stages.insert(stagePrefix(stage, 2));
            });
        };
        Progress progressWithin = recorder(stagesWithin);
        const RemeshResult within = remeshModel(input, params, progressWithin);
        params.refinementMaxQualityLoss = -100.0; // every round is
        Progress progressOver = recorder(stagesOver);
        const RemeshResult over = remeshModel(input, params, progressOver);
        const std::string roundCheck = "Refinement round 1: Validity (3/3)";
        QVERIFY(stagesWithin.count(roundCheck) == 1);
        QVERIFY2(stagesOver.count(roundCheck) == 0, "the unkept round was checked");
        QVERIFY(stagesOver.count("Refinement round 1: Mesh building (2/3)") == 1);
        qInfo("one fault, 500 sites: %d rounds run (%d kept) within the allowance, %d "
              "(%d kept) over it",
              within.refinementRoundsRun, within.refinementRounds, over.refinementRoundsRun,
              over.refinementRounds);
        QVERIFY(within.refinementRoundsRun >= 2);
        QVERIFY(over.validity.valid);
        QCOMPARE(over.refinementRoundsRun, 1);
        QCOMPARE(over.refinementRounds, 0);
        QCOMPARE(over.siteCount, over.sizedSiteCount);
    }

    // Four sheets around one line (a folded horizon crossing a 45° fault with no throw): the
    // dual gave fins along the line, duplicated in two sheets (line_fins.h). Without their
    // removal none of these runs was valid.
    void horizonCrossingDippingFaultStaysValid()
    {
        LayeredBoxParams bp;
        bp.size = Vec3(1000, 600, 400);
        bp.horizons = 2;
        bp.fault = true;
        bp.faultThrow = 0;
        bp.faultDipDegrees = 45;
        bp.foldAmplitude = 30;
        bp.edgeLength = 40;
        const Model input = recoverTopology(layeredBox(bp));
        QVERIFY(checkValidity(input).valid);
        auto crossingLines = [](const Model &m) {
            return test::countLines(
                m, [](int horizons, int faults) { return horizons == 2 && faults == 2; });
        };
        QCOMPARE(crossingLines(input), 2);
        for (const auto &[edge, seed] :
             {std::pair{150.0, 2u}, std::pair{90.0, 1u}, std::pair{60.0, 1u}}) {
            RemeshParams params;
            params.edgeLength = edge;
            params.iterations = 40;
            params.seed = seed;
            const RemeshResult result = remeshModel(input, params);
            const ValidityReport validity = checkValidity(result.model);
            QVERIFY2(validity.valid,
                     qPrintable(QStringLiteral("edge %1: %2")
                                    .arg(edge)
                                    .arg(validity.problems.empty()
                                             ? QString()
                                             : QString::fromStdString(
                                                 validity.problems.front().message))));
            QVERIFY(result.cleanup.lineFins > 0);
            QVERIFY(crossingLines(result.model) >= 2); // a corner may cut one
        }
    }
};

QTEST_GUILESS_MAIN(TestSurfaceRemesher)
#include "test_surface_remesher.moc"
