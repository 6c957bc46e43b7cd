#include "voronoi/restricted_delaunay.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <set>
#include <tuple>

namespace stratamesh {

RestrictedDelaunay restrictedDelaunay(const RestrictionDomain &domain,
                                      const RestrictedVoronoiDiagram &rvd)
{
    RestrictedDelaunay rdt;
    rdt.vertices = rvd.sites;
    std::set<std::tuple<int, int, int, int>> seenTriangles; // surface, sorted triple
    std::set<std::tuple<int, int, int>> seenEdges;          // line, pair
    for (const RvdVertex &v : rvd.vertices) {
        if (v.symbol.kind != RvdVertexKind::FaceVoronoiEdge)
            continue;
        const auto &s = v.symbol.sites;
        const int t = v.symbol.a;
        const int surface = domain.triangleSurface[t];
        if (!seenTriangles.emplace(surface, s[0], s[1], s[2]).second)
            continue;
        const Triangle &in = domain.triangles[t];
        const Vec3 normal = (domain.points[in[1]] - domain.points[in[0]])
                                .cross(domain.points[in[2]] - domain.points[in[0]]);
        const Vec3 &a = rvd.sites[s[0]], &b = rvd.sites[s[1]], &c = rvd.sites[s[2]];
        const bool flip = (b - a).cross(c - a).dot(normal) < 0;
        rdt.triangles.push_back(flip ? Triangle{s[0], s[2], s[1]} : Triangle{s[0], s[1], s[2]});
        rdt.triangleSurface.push_back(surface);
    }
    for (const RvdLinePiece &piece : rvd.linePieces) {
        for (int e = 0; e < 2; ++e) {
            const RvdSymbol &sym = rvd.vertices[piece.vertices[e]].symbol;
            if (sym.kind != RvdVertexKind::EdgeBisector)
                continue;
            if (seenEdges.emplace(piece.line, sym.sites[0], sym.sites[1]).second) {
                rdt.lineEdges.push_back({sym.sites[0], sym.sites[1]});
                rdt.lineEdgeLine.push_back(piece.line);
            }
        }
    }
    return rdt;
}

} // namespace stratamesh
