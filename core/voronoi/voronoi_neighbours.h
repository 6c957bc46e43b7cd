// Sites in 3D and their Voronoi neighbours from the Delaunay triangulation (thesis §1.1;
// CGAL Delaunay_triangulation_3 with exact predicates). Rebuilt at every CVT iteration.
//
// Neighbours are the Delaunay edges plus, where sites are cospherical (several Delaunay cells
// share one circumsphere) or coplanar on the hull, every pair of such a cluster. The Voronoi
// cell of a site is then exactly the intersection of the half-spaces of its neighbours under
// the symbolic perturbation of rvd_predicates.h, whatever triangulation CGAL chose for the
// degenerate cluster (a regular grid of sites is the typical case).
#pragma once

#include "model/model.h"

#include <memory>
#include <mutex>
#include <vector>

namespace stratamesh {

class SiteDelaunay {
public:
    SiteDelaunay();
    // Builds the triangulation of the sites. Exactly duplicated sites are kept but hidden: the
    // lowest index owns the point, the others have empty cells. Throws InputError on a
    // non-finite coordinate.
    explicit SiteDelaunay(std::vector<Vec3> sites);
    ~SiteDelaunay();
    SiteDelaunay(SiteDelaunay &&) noexcept;
    SiteDelaunay &operator=(SiteDelaunay &&) noexcept;

    int siteCount() const { return static_cast<int>(m_sites.size()); }
    const std::vector<Vec3> &sites() const { return m_sites; }
    const Vec3 &site(int i) const { return m_sites[i]; }
    // Affine dimension of the sites (3 in general; 2 when all are coplanar, ...).
    int dimension() const { return m_dimension; }
    bool isHidden(int i) const { return m_hidden[i] != 0; }

    // Voronoi neighbours of site i sorted by increasing distance |p_l − p_i| (ties by index).
    const int *neighboursBegin(int i) const { return m_neighbours.data() + m_offsets[i]; }
    const int *neighboursEnd(int i) const { return m_neighbours.data() + m_offsets[i + 1]; }
    // |p_l − p_i| in the same order.
    const double *neighbourDistances(int i) const { return m_distances.data() + m_offsets[i]; }
    int neighbourCount(int i) const { return m_offsets[i + 1] - m_offsets[i]; }
    // Undirected neighbour pairs (i < j), sorted.
    std::vector<std::array<int, 2>> neighbourPairs() const;

    // The site whose perturbed Voronoi cell contains q (exact), found by a greedy walk over
    // neighbours starting from hint (any visible site; −1 to start from a nearest-site search).
    int owner(const Vec3 &q, int hint = -1) const;

private:
    int approximateNearest(const Vec3 &q) const;
    template <class Triangulation> void keepLowestDuplicates(Triangulation &dt);

    std::vector<Vec3> m_sites;
    std::vector<char> m_hidden;
    std::vector<int> m_offsets;
    std::vector<int> m_neighbours;
    std::vector<double> m_distances;
    int m_dimension = -1;
    int m_firstVisible = -1;

    struct KdTree;
    mutable std::unique_ptr<KdTree> m_kdTree; // built on first use by owner(q, −1)
    mutable std::unique_ptr<std::once_flag> m_kdOnce;
};

} // namespace stratamesh
