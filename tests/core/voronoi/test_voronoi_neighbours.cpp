// Neighbour lists of the sites (voronoi/voronoi_neighbours.h) against brute force on random sites
// built in code: the k-nearest lists hold exactly the sites within their complete radius, sorted
// by distance; reused lists (NeighbourReuse) equal fresh ones within that radius and are not
// searched or copied again while the sites drift little; owner() is the nearest site.
#include "voronoi/voronoi_neighbours.h"

#include "core/voronoi/test_shapes.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

using namespace stratamesh;

namespace {

std::vector<int> listOf(const VoronoiNeighbours &n, int i)
{
    return {n.neighboursBegin(i), n.neighboursEnd(i)};
}

// Sites j ≠ i with |p_j − p_i| < radius, by brute force.
std::set<int> within(const std::vector<Vec3> &sites, int i, double radius)
{
    std::set<int> out;
    for (int j = 0; j < int(sites.size()); ++j)
        if (j != i && (sites[std::size_t(j)] - sites[std::size_t(i)]).norm() < radius)
            out.insert(j);
    return out;
}

// The listed sites closer than radius.
std::set<int> listedWithin(const VoronoiNeighbours &n, int i, double radius)
{
    std::set<int> out;
    for (int k = 0; k < n.neighbourCount(i); ++k)
        if (n.neighbourDistances(i)[k] < radius)
            out.insert(n.neighboursBegin(i)[k]);
    return out;
}

void verifyAgainstBruteForce(const VoronoiNeighbours &n, const std::vector<Vec3> &sites)
{
    for (int i = 0; i < n.siteCount(); ++i) {
        const double radius = n.completeRadius(i);
        QVERIFY2(radius >= 0.0 && std::isfinite(radius), qPrintable(QString::number(i)));
        QCOMPARE(listedWithin(n, i, radius), within(sites, i, radius));
        const std::vector<int> list = listOf(n, i);
        QVERIFY(std::find(list.begin(), list.end(), i) == list.end());
        for (int k = 0; k < n.neighbourCount(i); ++k) {
            const int j = list[std::size_t(k)];
            QCOMPARE(n.neighbourDistances(i)[k],
                     (sites[std::size_t(j)] - sites[std::size_t(i)]).norm());
            if (k > 0)
                QVERIFY(n.neighbourDistances(i)[k - 1] <= n.neighbourDistances(i)[k]);
        }
    }
}

} // namespace

class TestVoronoiNeighbours : public QObject {
    Q_OBJECT

private slots:
    void nearestListsEqualBruteForce()
    {
        const std::vector<Vec3> sites =
            test::randomPointsInBox(300, Vec3(0, 0, 0), Vec3(1, 2, 0.5), 7);
        const VoronoiNeighbours n(sites, NeighbourSearch::NearestNeighbours);
        QCOMPARE(n.siteCount(), 300);
        verifyAgainstBruteForce(n, sites);
    }

    // Delaunay lists hold every Voronoi neighbour; the nearest site is always one of them.
    void delaunayListsHoldTheNearestSite()
    {
        const std::vector<Vec3> sites =
            test::randomPointsInBox(200, Vec3(0, 0, 0), Vec3(1, 1, 1), 3);
        const VoronoiNeighbours n(sites);
        QCOMPARE(n.dimension(), 3);
        for (int i = 0; i < n.siteCount(); ++i) {
            int nearest = -1;
            for (int j = 0; j < n.siteCount(); ++j)
                if (j != i
                    && (nearest < 0
                        || (sites[std::size_t(j)] - sites[std::size_t(i)]).norm()
                               < (sites[std::size_t(nearest)] - sites[std::size_t(i)]).norm()))
                    nearest = j;
            QCOMPARE(n.neighboursBegin(i)[0], nearest);
        }
    }

    void ownerIsTheNearestSite()
    {
        const std::vector<Vec3> sites =
            test::randomPointsInBox(150, Vec3(0, 0, 0), Vec3(1, 1, 1), 11);
        const VoronoiNeighbours n(sites, NeighbourSearch::NearestNeighbours);
        const std::vector<Vec3> queries =
            test::randomPointsInBox(200, Vec3(0, 0, 0), Vec3(1, 1, 1), 12);
        for (const Vec3 &q : queries) {
            int best = 0;
            for (int j = 1; j < n.siteCount(); ++j)
                if ((sites[std::size_t(j)] - q).norm() < (sites[std::size_t(best)] - q).norm())
                    best = j;
            QCOMPARE(n.owner(q), best);
            QCOMPARE(n.owner(q, (best + 17) % n.siteCount()), best);
        }
    }

    // The CVT's reuse: one search, then lists reused while the sites drift less than maxDrift;
    // the reused lists equal a fresh search within their (smaller) complete radius, and the stored
    // lists are neither searched again nor reallocated. A large move searches again.
    void listsAreReusedWhileSitesDriftLittle()
    {
        std::vector<Vec3> sites = test::randomPointsInBox(400, Vec3(0, 0, 0), Vec3(1, 1, 1), 5);
        NeighbourReuse reuse;
        const VoronoiNeighbours first(sites, reuse);
        QCOMPARE(reuse.searches, 1);
        QCOMPARE(reuse.reuses, 0);
        QVERIFY(reuse.maxDrift > 0.0);
        verifyAgainstBruteForce(first, sites);
        const int *stored = reuse.lists.neighbours.data();
        const std::size_t storedSize = reuse.lists.neighbours.size();

        std::mt19937 rng(9);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int step = 1; step <= 3; ++step) {
            for (Vec3 &s : sites)
                s += Vec3(u(rng), u(rng), u(rng)).normalized() * (0.25 * reuse.maxDrift);
            const VoronoiNeighbours again(sites, reuse);
            QCOMPARE(reuse.searches, 1);
            QCOMPARE(reuse.reuses, step);
            QVERIFY(reuse.lists.neighbours.data() == stored);
            QCOMPARE(reuse.lists.neighbours.size(), storedSize);
            verifyAgainstBruteForce(again, sites);
            const VoronoiNeighbours fresh(sites, NeighbourSearch::NearestNeighbours);
            for (int i = 0; i < again.siteCount(); ++i) {
                QVERIFY(again.completeRadius(i) <= fresh.completeRadius(i));
                QCOMPARE(listedWithin(again, i, again.completeRadius(i)),
                         listedWithin(fresh, i, again.completeRadius(i)));
            }
        }
        // Past maxDrift (checked against the stored sites): a new search, new stored lists.
        for (Vec3 &s : sites)
            s += Vec3(1, 0, 0) * (2.0 * reuse.maxDrift);
        const VoronoiNeighbours moved(sites, reuse);
        QCOMPARE(reuse.searches, 2);
        QCOMPARE(reuse.reuses, 3);
        verifyAgainstBruteForce(moved, sites);
    }
};

QTEST_APPLESS_MAIN(TestVoronoiNeighbours)
#include "test_voronoi_neighbours.moc"
