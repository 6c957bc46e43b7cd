// The shells of a model's regions (model/region_shells.h): the pocket repair skips the flips that
// flipKeepsShells says change no shell, so each such flip, made for real, must leave the shells'
// sides as they were, on closed surfaces apart and next to the contacts of a fault network.
#include "model/region_shells.h"

#include "model/synthetic_models.h"
#include "model/topology.h"

#include <QtTest>

#include <algorithm>

using namespace stratamesh;

namespace {

// Flips a–b of surface s like the pocket repair: its triangle running a → b and the one running
// b → a become (a, d, c) and (d, b, c). False when it cannot (not such an edge, or c–d is one).
bool flip(Surface &surface, int a, int b)
{
    int inside = -1, outside = -1, c = -1, d = -1;
    for (std::size_t t = 0; t < surface.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Triangle &tri = surface.triangles[t];
            if (tri[k] == a && tri[(k + 1) % 3] == b) {
                inside = static_cast<int>(t);
                c = tri[(k + 2) % 3];
            } else if (tri[k] == b && tri[(k + 1) % 3] == a) {
                outside = static_cast<int>(t);
                d = tri[(k + 2) % 3];
            }
        }
    if (inside < 0 || outside < 0 || c == d)
        return false;
    for (const Triangle &tri : surface.triangles)
        if (std::count(tri.begin(), tri.end(), c) && std::count(tri.begin(), tri.end(), d))
            return false;
    surface.triangles[inside] = {a, d, c};
    surface.triangles[outside] = {d, b, c};
    return true;
}

// Sides per pocket, sorted, and the folds: what a flip that keeps the shells must not change.
struct ShellShape {
    std::vector<std::size_t> pocketSides;
    std::size_t folds = 0;
    bool operator==(const ShellShape &o) const
    {
        return pocketSides == o.pocketSides && folds == o.folds;
    }
};

ShellShape shapeOf(const Model &model)
{
    const RegionShells shells = analyseRegionShells(model);
    ShellShape shape;
    for (const RegionPocket &p : shells.pockets)
        shape.pocketSides.push_back(p.sides.size());
    std::sort(shape.pocketSides.begin(), shape.pocketSides.end());
    shape.folds = shells.folds.size();
    return shape;
}

// Flips every `stride`-th edge of surface s that flipKeepsShells accepts and checks the shells;
// returns how many were flipped and how many edges it refused.
std::pair<int, int> checkFlips(const Model &model, int s, int stride)
{
    const std::vector<int> counts = vertexSurfaceCounts(model);
    const ShellShape before = shapeOf(model);
    int flipped = 0, refused = 0, seen = 0;
    const std::vector<Triangle> &triangles = model.surfaces[s].triangles;
    for (const Triangle &tri : triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k], b = tri[(k + 1) % 3];
            if (!flipKeepsShells(model, s, counts, a, b)) {
                ++refused;
                continue;
            }
            if (seen++ % stride != 0)
                continue;
            Model flippedModel = model;
            if (!flip(flippedModel.surfaces[s], a, b))
                continue;
            ++flipped;
            if (!(shapeOf(flippedModel) == before))
                return {-1, refused};
        }
    return {flipped, refused};
}

} // namespace

class TestRegionShells : public QObject {
    Q_OBJECT

private slots:
    // One region inside two spheres apart: a pocket. No vertex of a sphere is on another
    // surface, so every flip keeps the shells.
    void flipsOnASphereApartKeepThePocket()
    {
        NestedSpheresParams p;
        p.subdivisions = 2;
        const Surface a = nestedSpheres(p).surfaces[0];
        p.centre = Vec3(10.0, 0.0, 0.0);
        p.innerRadius = 0.5;
        Surface b = nestedSpheres(p).surfaces[0];
        b.name = "apart";
        Model m;
        m.surfaces = {a, b};
        m.regions = {{"inside", {{0, false}, {1, false}}}};
        m.universe = {{0, true}, {1, true}};
        m = recoverTopology(m);
        QCOMPARE(shapeOf(m).pocketSides.size(), std::size_t(1));
        const auto [flipped, refused] = checkFlips(m, 0, 7);
        QVERIFY2(flipped >= 30, qPrintable(QString::number(flipped)));
        QCOMPARE(refused, 0);
    }

    // A fault network and the sample (a box whose sides hold the horizons' contacts): flips next
    // to contacts (one end on a line) are accepted and keep the shells.
    void flipsNextToContactsKeepTheShells_data()
    {
        QTest::addColumn<int>("model");
        QTest::newRow("fault network") << 0;
        QTest::newRow("sample") << 1;
    }

    void flipsNextToContactsKeepTheShells()
    {
        QFETCH(int, model);
        const Model m =
            recoverTopology(model == 0 ? faultNetworkBox(2, 30.0, 2, 20.0, 120.0) : sampleModel());
        int surfaces = 0;
        for (int s = 0; s < static_cast<int>(m.surfaces.size()); ++s) {
            const auto [flipped, refused] = checkFlips(m, s, 5);
            QVERIFY2(flipped >= 0, qPrintable(QString::fromStdString(m.surfaces[s].name)));
            if (flipped > 0 && refused > 0)
                ++surfaces;
        }
        QVERIFY(surfaces >= 4);
    }
};

QTEST_APPLESS_MAIN(TestRegionShells)
#include "test_region_shells.moc"
