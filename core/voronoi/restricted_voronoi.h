// The restricted Voronoi diagram (RVD) of sites to all surfaces and lines of a model at once
// (thesis §1.2.1–1.2.2, §4.4; Yan et al. 2009; Lévy & Bonneel 2013), with symbolic vertices.
//
// This is the public structure the remesher (thesis ch. 4) and the complexity measures (ch. 3)
// read. What it guarantees:
//   - Every RVD vertex is identified by its symbol (RvdSymbol): an input vertex, an input edge
//     (or line segment) ∩ bisector(i, j), or an input triangle ∩ Voronoi edge(i, j, k). A symbol
//     appears once in `vertices`, whatever the number of triangles, surfaces, lines or cells
//     sharing it, so every connectivity below is exact (no distance tolerance anywhere).
//   - Restricted polygons (cell ∩ input triangle) tile every triangle; line pieces (cell ∩
//     segment) tile every segment; both are consistent with each other on contact lines.
//   - Per cell: area, length, centroid, connected components on surfaces (per surface, through
//     shared input edges of that surface) and on lines (per line, through shared line vertices),
//     and the corners it contains.
//
// Typical use:
//   const RestrictionDomain domain = makeRestrictionDomain(model);
//   const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(domain, sites);
//   for (int c : rvd.cells[i].surfaceComponents) { rvd.surfaceComponents[c].centroid ... }
//   A dual triangle of the remesher = the three cells of a FaceVoronoiEdge vertex; the
//   components holding it are those of the polygons listed by polygonsOfVertex(v).
#pragma once

#include "common/progress.h"
#include "voronoi/restriction_domain.h"
#include "voronoi/voronoi_neighbours.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace stratamesh {

enum class RvdVertexKind : std::uint8_t {
    InputVertex,     // a domain point
    EdgeBisector,    // input edge or line segment (a, b) ∩ bisector(sites[0], sites[1])
    FaceVoronoiEdge, // input triangle a ∩ Voronoi edge(sites[0], sites[1], sites[2])
};

struct RvdSymbol {
    RvdVertexKind kind = RvdVertexKind::InputVertex;
    int a = -1; // point (InputVertex, EdgeBisector) or triangle (FaceVoronoiEdge)
    int b = -1; // second point of the edge (EdgeBisector, a < b), else −1
    std::array<int, 3> sites{-1, -1, -1}; // increasing; unused entries −1

    bool operator==(const RvdSymbol &o) const
    {
        return kind == o.kind && a == o.a && b == o.b && sites == o.sites;
    }
    bool operator!=(const RvdSymbol &o) const { return !(*this == o); }
    std::string toString() const;
};

struct RvdSymbolHash {
    std::size_t operator()(const RvdSymbol &s) const;
};

struct RvdVertex {
    RvdSymbol symbol;
    Vec3 position;     // computed from the symbol in a canonical order
    double error = 0;  // proven bound on |position − exact point|
    int triangle = -1; // lowest domain triangle containing it (−1: only on lines)
    int surface = -1;  // surface of that triangle
};

// A restricted polygon: the part of input triangle `triangle` inside the cell of `site`.
struct RvdPolygon {
    int site = -1;
    int triangle = -1;
    int surface = -1;
    int first = 0; // its vertices are polygonVertices[first .. first + count)
    int count = 0;
    double area = 0;
    Vec3 centroid = Vec3::Zero();
    int component = -1; // index in surfaceComponents
};

// A restricted line piece: the part of segment `segment` inside the cell of `site`.
struct RvdLinePiece {
    int site = -1;
    int segment = -1;
    int line = -1;
    std::array<int, 2> vertices{-1, -1}; // RVD vertices in the segment's direction
    double length = 0;
    int component = -1; // index in lineComponents
};

// A connected component of (cell ∩ one surface).
struct RvdSurfaceComponent {
    int site = -1;
    int surface = -1;
    std::vector<int> polygons; // increasing
    double area = 0;
    Vec3 centroid = Vec3::Zero();
};

// A connected component of (cell ∩ one line): a chain of pieces in line order.
struct RvdLineComponent {
    int site = -1;
    int line = -1;
    std::vector<int> pieces;         // in line order
    std::array<int, 2> ends{-1, -1}; // RVD vertices at both ends; {−1, −1} for a whole closed line
    double length = 0;
    Vec3 centroid = Vec3::Zero();
};

struct RestrictedCell {
    double area = 0;                    // on all surfaces
    double length = 0;                  // on all lines
    Vec3 centroid = Vec3::Zero();       // area centroid (the site itself when area = 0)
    std::vector<int> surfaceComponents; // indices in RestrictedVoronoiDiagram::surfaceComponents
    std::vector<int> lineComponents;    // indices in lineComponents
    std::vector<int> corners;           // indices in RestrictionDomain::corners
};

struct RestrictedVoronoiDiagram {
    std::vector<Vec3> sites;
    std::vector<RvdVertex> vertices;
    std::vector<RvdPolygon> polygons; // grouped by triangle, triangles in increasing order
    std::vector<int> polygonVertices; // counter-clockwise as the input triangle
    // Support of the polygon edge from vertex k to k + 1: a site j ≥ 0 (the edge lies on
    // bisector(site, j): cell j is across) or −1 − e (edge e of the input triangle, from its
    // corner e to corner (e + 1) % 3).
    std::vector<int> polygonSupports;
    std::vector<RvdLinePiece> linePieces; // grouped by segment, in line order
    std::vector<RvdSurfaceComponent> surfaceComponents;
    std::vector<RvdLineComponent> lineComponents;
    std::vector<RestrictedCell> cells; // one per site
    std::vector<int> cornerSites;      // per domain corner, the site whose cell holds it

    // Polygons having vertex v (CSR).
    std::vector<int> vertexPolygonOffsets;
    std::vector<int> vertexPolygons;

    const int *polygonVerticesBegin(int p) const
    {
        return polygonVertices.data() + polygons[p].first;
    }
    const int *polygonSupportsBegin(int p) const
    {
        return polygonSupports.data() + polygons[p].first;
    }
    std::vector<int> polygonsOfVertex(int v) const
    {
        return {vertexPolygons.begin() + vertexPolygonOffsets[v],
                vertexPolygons.begin() + vertexPolygonOffsets[v + 1]};
    }
};

// Computes the diagram (neighbours of the sites included: the k nearest sites by default, see
// voronoi_neighbours.h; the diagram is the same with the Delaunay triangulation). Parallel with
// oneTBB; the result is identical for any number of threads. Throws InputError on non-finite sites,
// Cancelled when progress is cancelled.
RestrictedVoronoiDiagram
computeRestrictedVoronoi(const RestrictionDomain &domain, const std::vector<Vec3> &sites,
                         Progress &progress = Progress::none(),
                         NeighbourSearch search = NeighbourSearch::NearestNeighbours);
RestrictedVoronoiDiagram computeRestrictedVoronoi(const RestrictionDomain &domain,
                                                  const VoronoiNeighbours &delaunay,
                                                  Progress &progress = Progress::none());

} // namespace stratamesh
