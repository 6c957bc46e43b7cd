// Vertex-dual cells of Voronoi vertices whose cells are cut by the surfaces (thesis §5.3.3,
// Fig 5.4, Fig 5.5): each of the four Voronoi cells meeting at the vertex gives the points of its
// part on the vertex's side, its site when the cell meets no surface, else the remesh points of
// the site on the surfaces bounding the vertex's region. When each part gives exactly one point
// (one intersection component, Table 5.1 "cell part, 1 → 1 boundary vertex") the cell is a tet
// linking interior sites and remesh points. A part crossed twice gives two points (Fig 5.4): the
// 5–8-vertex cells are split from their centroid into the tets of their hull faces (§5.4) when
// their points are in convex position with no four coplanar on the hull. A site with more points
// on the region's boundary is undefined (Fig 5.6): when there is one such site, the one or two of
// its points giving the best smallest dihedral angle are taken (§5.4 "chosen by quality"). The
// others (and cells still inverted, flat or not convex) are left to the constrained fill.
//
// The region of a Voronoi vertex comes from its uncut sites (their cells meet no surface, so the
// vertex lies in their region) and is carried to the other vertices along Voronoi edges that cross
// no surface (Algorithm 5.1's propagation, here from inside). A tet is kept only when it keeps
// the orientation of the sites' Delaunay tet, has no dihedral angle under the bound, holds no
// remesh vertex and is reached from its Voronoi vertex without crossing a surface; the caller
// then rejects those whose faces cross the surfaces or other cells. A tet beside one rejected for
// its shape goes too: the lone place left would be filled with the same sliver (a flat tet of
// four surface points, most often).
#pragma once

#include "complexity/indexed_delaunay.h"
#include "model/model.h"

#include <array>
#include <cstddef>
#include <vector>

namespace stratamesh {

struct CutVertexTet {
    // Remesh vertex ids (< remesh.vertices.size()), remesh.vertices.size() + site index, or after
    // those remesh.vertices.size() + sites.size() + index in the centroids of split cells.
    std::array<int, 4> nodes{};
    int region = -1;
    indexed_delaunay::Delaunay::Cell_handle dual; // the Delaunay tet of the four sites
};

struct CutVertexStats {
    std::size_t candidates = 0;      // finite Delaunay tets with a cut site
    std::size_t noRegion = 0;        // Voronoi vertex outside the model or not reached
    std::size_t manyPoints = 0;      // a cut site with no point or over 6, or two with over 2
    std::size_t undefinedChosen = 0; // cells with a site of 3–6 points, its best 1 or 2 taken
    std::size_t split = 0;           // 5–8-vertex cells split from their centroid (before checks)
    std::size_t rejectedShape = 0;   // inverted, or a dihedral angle under the bound
    std::size_t rejectedSurface = 0; // holds a remesh vertex, or its centroid is across a surface
    std::size_t besideSliver = 0;    // a face neighbour was rejected for its shape
};

// `cut[s]`: site s has remesh points (pointSite[v] == s for some v).
std::vector<CutVertexTet> findCutVertexTets(const indexed_delaunay::Delaunay &dt,
                                            const Model &remesh, const std::vector<Vec3> &sites,
                                            const std::vector<int> &pointSite,
                                            const std::vector<char> &cut, double minDihedralDegrees,
                                            std::vector<Vec3> &centroids, CutVertexStats &stats);

} // namespace stratamesh
