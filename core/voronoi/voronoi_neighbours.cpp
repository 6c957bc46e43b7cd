#include "voronoi/voronoi_neighbours.h"

#include "common/error.h"
#include "voronoi/delaunay_neighbours.h"
#include "voronoi/rvd_predicates.h"

#include <nanoflann.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

namespace stratamesh {
namespace {

// Nearest sites listed per site; beyond them, sitesBeyondList() completes a list on demand.
constexpr int kNearest = 16;

// nanoflann result set for the k nearest that may start with guesses, so that the search prunes
// from the start. Every point lies in one leaf, so only the guesses can come twice: they are
// marked (marks[j] == query) and skipped. Sorted by squared distance; equal distances keep the
// order of arrival, like nanoflann's KNNResultSet.
class SeededKnn {
public:
    SeededKnn(int capacity, int *indices, double *dists, int *marks, int query)
        : m_capacity(capacity), m_indices(indices), m_dists(dists), m_marks(marks), m_query(query)
    {
    }
    // Guesses (distinct points, sorted by (squared distance, index)), before the search.
    void seed(const std::pair<double, int> *guesses, int count)
    {
        m_count = std::min(count, m_capacity);
        for (int a = 0; a < m_count; ++a) {
            m_dists[a] = guesses[a].first;
            m_indices[a] = guesses[a].second;
            m_marks[guesses[a].second] = m_query;
        }
    }
    std::size_t size() const { return static_cast<std::size_t>(m_count); }
    bool full() const { return m_count == m_capacity; }
    double worstDist() const
    {
        return m_count == m_capacity ? m_dists[m_capacity - 1] : std::numeric_limits<double>::max();
    }
    bool addPoint(double dist, int index)
    {
        if (m_marks[index] == m_query)
            return true;
        int a = m_count;
        for (; a > 0 && m_dists[a - 1] > dist; --a)
            if (a < m_capacity) {
                m_dists[a] = m_dists[a - 1];
                m_indices[a] = m_indices[a - 1];
            }
        if (a < m_capacity) {
            m_dists[a] = dist;
            m_indices[a] = index;
        }
        if (m_count < m_capacity)
            ++m_count;
        return true;
    }

private:
    int m_capacity, m_count = 0;
    int *m_indices;
    double *m_dists;
    int *m_marks;
    int m_query;
};

// Squared distance as nanoflann's L2_Simple_Adaptor computes it.
inline double squaredDistance(const Vec3 &a, const Vec3 &b)
{
    double s = 0;
    for (int c = 0; c < 3; ++c) {
        const double d = a[c] - b[c];
        s += d * d;
    }
    return s;
}

} // namespace

struct VoronoiNeighbours::KdTree {
    struct Cloud {
        const Vec3 *points = nullptr;
        std::size_t count = 0;
        std::size_t kdtree_get_point_count() const { return count; }
        double kdtree_get_pt(std::size_t i, std::size_t dim) const
        {
            return points[i][static_cast<int>(dim)];
        }
        template <class B>
        bool kdtree_get_bbox(B &) const
        {
            return false;
        }
    };
    using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                      Cloud, 3, int>;
    Cloud cloud;
    std::unique_ptr<Index> index;
};

VoronoiNeighbours::VoronoiNeighbours() : m_kdOnce(std::make_unique<std::once_flag>()) {}
VoronoiNeighbours::~VoronoiNeighbours() = default;
VoronoiNeighbours::VoronoiNeighbours(VoronoiNeighbours &&) noexcept = default;
VoronoiNeighbours &VoronoiNeighbours::operator=(VoronoiNeighbours &&) noexcept = default;

VoronoiNeighbours::VoronoiNeighbours(std::vector<Vec3> sites, NeighbourSearch search,
                                     const NeighbourHints *hints)
    : m_search(search), m_sites(std::move(sites)), m_kdOnce(std::make_unique<std::once_flag>())
{
    checkSites();
    if (search == NeighbourSearch::Delaunay) {
        detail::DelaunayLists lists = detail::delaunayNeighbourLists(m_sites);
        m_hidden = std::move(lists.hidden);
        m_offsets = std::move(lists.offsets);
        m_neighbours = std::move(lists.neighbours);
        m_dimension = lists.dimension;
        if (m_offsets.empty())
            m_offsets.assign(m_sites.size() + 1, 0);
        sortByDistance();
    } else {
        buildNearest(hints); // sorted already
    }
    findFirstVisible();
}

VoronoiNeighbours::VoronoiNeighbours(std::vector<Vec3> sites, NeighbourReuse &reuse)
    : m_search(NeighbourSearch::NearestNeighbours), m_sites(std::move(sites)),
      m_kdOnce(std::make_unique<std::once_flag>())
{
    checkSites();
    if (reuseNearest(reuse)) {
        ++reuse.reuses;
    } else {
        buildNearest(&reuse.lists);
        ++reuse.searches;
        reuse.sites = m_sites;
        exportHints(reuse.lists);
        reuse.complete = m_complete;
        // A list reaches about the 16th nearest site, two spacings away, and a cell's security
        // radius is about 1.2 spacings. On modelA5 (5000 sites, 100 iterations, callgrind),
        // 0.1, 0.2 and 0.3 of the median list radius gave 43, 22 and 12 searches, and the
        // sites the cut lists lack, fetched from the kd-tree, cost 0.2e9, 0.45e9 and 4.9e9
        // instructions: past 0.2 the kd-tree work explodes, so 0.15 keeps a margin.
        std::vector<double> radii;
        for (double r : m_complete)
            if (std::isfinite(r))
                radii.push_back(r);
        if (!radii.empty()) {
            std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
            reuse.maxDrift = 0.15 * radii[radii.size() / 2];
        } else {
            reuse.maxDrift = 0.0;
        }
    }
    findFirstVisible();
}

void VoronoiNeighbours::findFirstVisible()
{
    for (int s = 0; s < siteCount() && m_firstVisible < 0; ++s)
        if (!m_hidden[s])
            m_firstVisible = s;
}

void VoronoiNeighbours::checkSites() const
{
    if (m_sites.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 32))
        throw InputError("too many sites: " + std::to_string(m_sites.size()));
    for (std::size_t i = 0; i < m_sites.size(); ++i)
        if (!m_sites[i].allFinite())
            throw InputError("site " + std::to_string(i) + " has a non-finite coordinate");
}

bool VoronoiNeighbours::reuseNearest(const NeighbourReuse &reuse)
{
    const int n = siteCount();
    if (n == 0 || reuse.sites.size() != m_sites.size() || reuse.complete.size() != m_sites.size()
        || reuse.lists.offsets.size() != m_sites.size() + 1)
        return false;
    std::vector<double> drift(n);
    for (int i = 0; i < n; ++i)
        drift[i] = (m_sites[i] - reuse.sites[i]).norm();
    const double largest = *std::max_element(drift.begin(), drift.end());
    if (!(largest <= reuse.maxDrift))
        return false;
    const int slots = kNearest;
    m_neighbours.assign(static_cast<std::size_t>(n) * slots, -1);
    m_distances.assign(m_neighbours.size(), 0.0);
    m_complete.assign(n, std::numeric_limits<double>::infinity());
    std::atomic<bool> duplicate{false};
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 512), [&](const tbb::blocked_range<int> &r) {
        std::pair<double, int> kept[kNearest];
        for (int i = r.begin(); i < r.end(); ++i) {
            // Unlisted sites were at least `complete` away; each end moved at most its drift.
            // The margin covers the rounding of the drifts and of the distances.
            const double old = reuse.complete[i];
            const double radius =
                std::isfinite(old) ? (old - drift[i] - largest) * (1 - 1e-12) : old;
            int count = 0;
            for (int k = reuse.lists.offsets[i]; k < reuse.lists.offsets[i + 1] && count < slots;
                 ++k) {
                const int j = reuse.lists.neighbours[k];
                const double d = std::sqrt(squaredDistance(m_sites[j], m_sites[i]));
                if (d == 0.0)
                    duplicate.store(
                        true,
                        std::memory_order_relaxed); // hidden sites: the full search sorts them out
                if (d < radius)
                    kept[count++] = {d, j};
            }
            // Sorted by the old distances: nearly sorted by the new ones.
            for (int a = 1; a < count; ++a)
                for (int b = a; b > 0 && kept[b] < kept[b - 1]; --b)
                    std::swap(kept[b], kept[b - 1]);
            for (int a = 0; a < count; ++a) {
                m_neighbours[static_cast<std::size_t>(i) * slots + a] = kept[a].second;
                m_distances[static_cast<std::size_t>(i) * slots + a] = kept[a].first;
            }
            m_complete[i] = std::max(radius, 0.0);
        }
    });
    if (duplicate.load())
        return false;
    compactSlots(slots);
    m_hidden.assign(n, 0);
    return true;
}

const VoronoiNeighbours::KdTree &VoronoiNeighbours::kdTree() const
{
    std::call_once(*m_kdOnce, [this] {
        m_kdTree = std::make_unique<KdTree>();
        m_kdTree->cloud.points = m_sites.data();
        m_kdTree->cloud.count = m_sites.size();
        // The constructor builds the index (leaves of 10: fastest for the k-nearest lists).
        m_kdTree->index = std::make_unique<KdTree::Index>(
            3, m_kdTree->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    });
    return *m_kdTree;
}

void VoronoiNeighbours::buildNearest(const NeighbourHints *hints)
{
    const int n = siteCount();
    const int k = std::min(n, kNearest + 1); // the site itself comes back too
    m_neighbours.assign(static_cast<std::size_t>(n) * (k - 1 > 0 ? k - 1 : 0), -1);
    m_complete.assign(n, std::numeric_limits<double>::infinity());
    m_hidden.assign(n, 0);
    const KdTree &tree = kdTree();
    m_distances.assign(m_neighbours.size(), 0.0);
    // Queried in the tree's leaf order (nearby sites one after another: the same nodes stay in
    // cache); each list is sorted by distance here, as sortByDistance() would.
    const auto &order = tree.index->vAcc;
    const bool useHints = hints && hints->offsets.size() == static_cast<std::size_t>(n) + 1
                          && hints->offsets.back() == static_cast<int>(hints->neighbours.size());
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 512), [&](const tbb::blocked_range<int> &r) {
        std::vector<int> ids(k);
        std::vector<double> d2(k);
        // Plain buffers indexed by hand: the per-site bookkeeping around the search cost as much
        // as a third of the search itself through push_back/erase.
        std::vector<std::pair<double, int>> sortedBuffer(k), guesses(1);
        std::pair<double, int> *const sorted = sortedBuffer.data();
        std::vector<int> marks(n, -1);
        for (int position = r.begin(); position < r.end(); ++position) {
            const int i = order[position];
            const double query[3] = {m_sites[i].x(), m_sites[i].y(), m_sites[i].z()};
            const int hintCount = useHints ? hints->offsets[i + 1] - hints->offsets[i] : 0;
            if (static_cast<int>(guesses.size()) < hintCount + 1)
                guesses.resize(hintCount + 1);
            std::pair<double, int> *const g = guesses.data();
            int count = 0;
            g[count++] = {0.0, i};
            for (int h = 0; h < hintCount; ++h) {
                const int j = hints->neighbours[hints->offsets[i] + h];
                if (j >= 0 && j < n && j != i)
                    g[count++] = {squaredDistance(m_sites[j], m_sites[i]), j};
            }
            // The hints are the previous list, sorted by the previous distances: nearly sorted,
            // which an insertion sort handles in about one comparison per guess.
            for (int a = 1; a < count; ++a)
                for (int b = a; b > 0 && g[b] < g[b - 1]; --b)
                    std::swap(g[b], g[b - 1]);
            int distinct = count > 0 ? 1 : 0; // as std::unique
            for (int a = 1; a < count; ++a)
                if (!(g[a] == g[distinct - 1]))
                    g[distinct++] = g[a];
            SeededKnn result(k, ids.data(), d2.data(), marks.data(), i);
            result.seed(g, distinct);
            tree.index->findNeighbors(result, query, nanoflann::SearchParams());
            const std::size_t found = result.size();
            int listed = 0;
            double farthest = 0;
            for (std::size_t a = 0; a < found; ++a) {
                if (ids[a] == i)
                    continue;
                // d2 holds |p_j − p_i|² summed as Eigen's squaredNorm sums it: the same bits.
                const double d = std::sqrt(d2[a]);
                if (listed < k - 1)
                    sorted[listed++] = {d, ids[a]};
                farthest = std::max(farthest, d);
                if (d2[a] == 0 && m_sites[ids[a]] == m_sites[i] && ids[a] < i)
                    m_hidden[i] = 1; // a lower index owns this point
            }
            // Found in squared-distance order: (distance, index) order is almost the same.
            for (int a = 1; a < listed; ++a)
                for (int b = a; b > 0 && sorted[b] < sorted[b - 1]; --b)
                    std::swap(sorted[b], sorted[b - 1]);
            const std::size_t base = static_cast<std::size_t>(i) * (k - 1);
            for (int a = 0; a < listed; ++a) {
                m_neighbours[base + a] = sorted[a].second;
                m_distances[base + a] = sorted[a].first;
            }
            // All sites strictly closer than the farthest found one are listed, unless the
            // tree returned fewer than asked (then every site is listed).
            if (static_cast<int>(found) == k && k < n)
                m_complete[i] = farthest;
        }
    });
    // Every list has k − 1 slots; unused ones only when the site itself was missed, or k > n.
    compactSlots(k > 1 ? k - 1 : 0);
}

void VoronoiNeighbours::compactSlots(int slots)
{
    const int n = siteCount();
    m_offsets.assign(n + 1, 0);
    if (std::find(m_neighbours.begin(), m_neighbours.end(), -1) == m_neighbours.end()) {
        for (int i = 0; i < n; ++i) // full lists skip the serial copy
            m_offsets[i + 1] = (i + 1) * slots;
        return;
    }
    std::size_t used = 0;
    for (int i = 0; i < n; ++i) {
        for (int a = 0; a < slots; ++a) {
            const std::size_t from = static_cast<std::size_t>(i) * slots + a;
            if (m_neighbours[from] >= 0) {
                m_neighbours[used] = m_neighbours[from];
                m_distances[used] = m_distances[from];
                ++used;
            }
        }
        m_offsets[i + 1] = static_cast<int>(used);
    }
    m_neighbours.resize(used);
    m_distances.resize(used);
}

void VoronoiNeighbours::sortByDistance()
{
    const int n = siteCount();
    m_distances.resize(m_neighbours.size());
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 256), [&](const tbb::blocked_range<int> &r) {
        std::vector<std::pair<double, int>> tmp;
        for (int i = r.begin(); i < r.end(); ++i) {
            tmp.clear();
            for (int k = m_offsets[i]; k < m_offsets[i + 1]; ++k)
                tmp.emplace_back((m_sites[m_neighbours[k]] - m_sites[i]).norm(), m_neighbours[k]);
            std::sort(tmp.begin(), tmp.end());
            for (std::size_t k = 0; k < tmp.size(); ++k) {
                m_distances[m_offsets[i] + k] = tmp[k].first;
                m_neighbours[m_offsets[i] + k] = tmp[k].second;
            }
        }
    });
}

void VoronoiNeighbours::sitesBeyondList(int i, double radius,
                                        std::vector<std::pair<double, int>> &out) const
{
    out.clear();
    const double complete = completeRadius(i);
    if (!(radius >= complete))
        return;
    const double query[3] = {m_sites[i].x(), m_sites[i].y(), m_sites[i].z()};
    thread_local std::vector<std::pair<int, double>> matches; // keeps its memory between calls
    matches.clear();
    nanoflann::SearchParams params;
    params.sorted = false;
    // A little wider than asked: distances are recomputed and filtered exactly as in the lists.
    const double r = radius * (1 + 1e-9) + 1e-300;
    kdTree().index->radiusSearch(query, r * r, matches, params);
    // Clearly inside the complete radius (margin far above the rounding of d2 and of the norm):
    // listed already, no square root needed.
    const double inside = complete * complete * (1 - 1e-6);
    for (const auto &[j, d2] : matches) {
        if (j == i || d2 < inside)
            continue;
        const double d = (m_sites[j] - m_sites[i]).norm();
        if (d > radius || d < complete)
            continue;
        // At exactly the complete radius, a site may be listed already (ties cut the k nearest).
        bool listed = false;
        for (int k = m_offsets[i + 1] - 1; k >= m_offsets[i] && m_distances[k] >= d; --k)
            listed = listed || m_neighbours[k] == j;
        if (!listed)
            out.emplace_back(d, j);
    }
    std::sort(out.begin(), out.end());
}

int VoronoiNeighbours::approximateNearest(const Vec3 &q) const
{
    int index = 0;
    double distance = 0;
    const double query[3] = {q.x(), q.y(), q.z()};
    kdTree().index->knnSearch(query, 1, &index, &distance);
    return index;
}

int VoronoiNeighbours::owner(const Vec3 &q, int hint) const
{
    if (m_firstVisible < 0)
        return -1;
    int c = (hint >= 0 && hint < siteCount() && !m_hidden[hint]) ? hint : approximateNearest(q);
    if (m_hidden[c])
        c = m_firstVisible;
    std::vector<std::pair<double, int>> farther;
    for (;;) {
        const Vec3 &pc = m_sites[c];
        // Beyond twice the distance to q, no site can be closer to q (security radius).
        const double limit = 2.0 * (q - pc).norm() * (1.0 + 1e-12);
        const int *nb = neighboursBegin(c);
        const double *dist = neighbourDistances(c);
        const int count = neighbourCount(c);
        int next = -1;
        int k = 0;
        for (; k < count && dist[k] <= limit; ++k) {
            if (rvd::sideOfInputVertex(q, pc, c, m_sites[nb[k]], nb[k]) < 0) {
                next = nb[k];
                break;
            }
        }
        if (next < 0 && k == count && limit >= completeRadius(c)) {
            sitesBeyondList(c, limit, farther);
            for (const auto &[d, l] : farther)
                if (rvd::sideOfInputVertex(q, pc, c, m_sites[l], l) < 0) {
                    next = l;
                    break;
                }
        }
        if (next < 0)
            return c;
        c = next;
    }
}

} // namespace stratamesh
