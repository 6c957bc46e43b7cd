// Sites in 3D and, for each, the sites whose bisectors may bound its Voronoi cell, sorted by
// distance: what the restricted Voronoi diagram clips with (thesis §1.1, §1.2.2). Rebuilt at
// every CVT iteration. Two ways to get them, giving the same exact diagram:
//
//  - Delaunay (this class's default): the Delaunay neighbours (CGAL Delaunay_triangulation_3, exact
//    predicates) plus, where sites are cospherical (several Delaunay cells share one sphere) or
//    cocircular on the hull, every pair of such a cluster, so that the list holds every
//    neighbour of the perturbed diagram of rvd_predicates.h whatever triangulation CGAL chose
//    for the degenerate cluster (a regular grid of sites is the typical case).
//  - NearestNeighbours (what the CVT and computeRestrictedVoronoi use): the k nearest sites
//    from a kd-tree (nanoflann), with the radius within which the list is complete; a user
//    that needs farther sites asks sitesBeyondList(). With the
//    security radius (clipping stops at twice the farthest polygon vertex), any complete list
//    of nearby sites gives the exact cell (Lévy & Bonneel 2013, "Variational anisotropic
//    surface meshing with Voronoi parallel linear enumeration", §4). Parallel, and faster than
//    the Delaunay triangulation, which runs on one thread.
#pragma once

#include "model/model.h"

#include <limits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace stratamesh {

enum class NeighbourSearch { Delaunay, NearestNeighbours };

// Sites likely near each site, to start the k-nearest searches from (typically the lists of the
// previous CVT evaluation: the sites moved little). They only make the search faster: the
// lists found are the same.
struct NeighbourHints {
    std::vector<int> offsets; // per site, CSR over neighbours; empty: no hints
    std::vector<int> neighbours;
};

// Lists searched for earlier sites, kept across CVT evaluations. While every site stays within
// `maxDrift` of where the lists were searched, site i's list still holds every site closer than
// its complete radius less its own drift and the largest drift (no unlisted site can have come
// nearer than that), which is all the security radius usually needs: the k-nearest search is
// skipped, and the lists, cut at that radius and sorted by the current distances, clip the same
// bisectors in the same order as fresh ones would (the same diagram, to the bit).
struct NeighbourReuse {
    std::vector<Vec3> sites; // where the lists were searched
    NeighbourHints lists;
    std::vector<double> complete;
    double maxDrift = 0.0; // set at each search from the lists' radii
    int searches = 0;      // k-nearest searches made
    int reuses = 0;        // evaluations that reused the lists
};

class VoronoiNeighbours {
public:
    VoronoiNeighbours();
    // Exactly duplicated sites are kept but hidden: the lowest index owns the point, the others
    // have empty cells. Throws InputError on a non-finite coordinate.
    explicit VoronoiNeighbours(std::vector<Vec3> sites,
                               NeighbourSearch search = NeighbourSearch::Delaunay,
                               const NeighbourHints *hints = nullptr);
    // NearestNeighbours lists, reusing `reuse` when the sites moved little, else searched afresh
    // (seeded with the old lists) and stored into it.
    VoronoiNeighbours(std::vector<Vec3> sites, NeighbourReuse &reuse);
    ~VoronoiNeighbours();
    VoronoiNeighbours(VoronoiNeighbours &&) noexcept;
    VoronoiNeighbours &operator=(VoronoiNeighbours &&) noexcept;

    NeighbourSearch search() const { return m_search; }
    int siteCount() const { return static_cast<int>(m_sites.size()); }
    const std::vector<Vec3> &sites() const { return m_sites; }
    const Vec3 &site(int i) const { return m_sites[i]; }
    // Delaunay: affine dimension of the sites (3 in general; 2 when all are coplanar, ...).
    // NearestNeighbours: −1 (not computed).
    int dimension() const { return m_dimension; }
    bool isHidden(int i) const { return m_hidden[i] != 0; }

    // Neighbours of site i sorted by increasing distance |p_l − p_i| (ties by index).
    const int *neighboursBegin(int i) const { return m_neighbours.data() + m_offsets[i]; }
    const int *neighboursEnd(int i) const { return m_neighbours.data() + m_offsets[i + 1]; }
    // |p_l − p_i| in the same order.
    const double *neighbourDistances(int i) const { return m_distances.data() + m_offsets[i]; }
    int neighbourCount(int i) const { return m_offsets[i + 1] - m_offsets[i]; }
    // Every site closer to site i than this is in its list (infinite for Delaunay lists, which
    // hold all Voronoi neighbours).
    double completeRadius(int i) const
    {
        return m_complete.empty() ? std::numeric_limits<double>::infinity() : m_complete[i];
    }
    // The sites within `radius` of site i that its list lacks (distance ≥ completeRadius(i) and
    // not listed), as (distance, site) sorted like the lists.
    void sitesBeyondList(int i, double radius, std::vector<std::pair<double, int>> &out) const;

    // The lists as hints for the next sites (NearestNeighbours: same sites count expected).
    void exportHints(NeighbourHints &hints) const
    {
        hints.offsets = m_offsets;
        hints.neighbours = m_neighbours;
    }

    // The site whose perturbed Voronoi cell contains q (exact), found by a greedy walk over
    // neighbours starting from hint (any visible site; −1 to start from a nearest-site search).
    int owner(const Vec3 &q, int hint = -1) const;

private:
    struct KdTree;
    const KdTree &kdTree() const;
    int approximateNearest(const Vec3 &q) const;
    void buildNearest(const NeighbourHints *hints);
    bool reuseNearest(const NeighbourReuse &reuse);
    // Drops the unused (−1) slots of lists laid out `slots` per site, and sets the offsets.
    void compactSlots(int slots);
    void checkSites() const;
    void findFirstVisible();
    void sortByDistance();

    NeighbourSearch m_search = NeighbourSearch::Delaunay;
    std::vector<Vec3> m_sites;
    std::vector<char> m_hidden;
    std::vector<int> m_offsets;
    std::vector<int> m_neighbours;
    std::vector<double> m_distances;
    std::vector<double> m_complete; // empty for Delaunay lists
    int m_dimension = -1;
    int m_firstVisible = -1;

    mutable std::unique_ptr<KdTree> m_kdTree; // built on first use
    mutable std::unique_ptr<std::once_flag> m_kdOnce;
};

} // namespace stratamesh
