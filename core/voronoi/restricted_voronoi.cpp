#include "voronoi/restricted_voronoi.h"

#include "voronoi/cell_clipper.h"
#include "voronoi/cell_integrals.h"
#include "voronoi/polygon_integrals.h"
#include "voronoi/restricted_voronoi_cells.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <unordered_map>

namespace stratamesh {
namespace {

constexpr int kChunk = 256;

struct LocalVertex {
    RvdSymbol symbol;
    Vec3 position;
    double error;
};

struct LocalPolygon {
    int site, triangle, first, count;
    double area;
    Vec3 centroid;
};

struct LocalPiece {
    int site, segment;
    RvdSymbol ends[2];
    double length;
};

struct Chunk {
    std::vector<LocalPolygon> polygons;
    std::vector<RvdSymbol> vertices;
    std::vector<int> supports;
    std::vector<LocalPiece> pieces;
};

RvdSymbol inputVertexSymbol(int point)
{
    RvdSymbol s;
    s.kind = RvdVertexKind::InputVertex;
    s.a = point;
    return s;
}

RvdSymbol edgeSymbol(int a, int b, int s0, int s1)
{
    RvdSymbol s;
    s.kind = RvdVertexKind::EdgeBisector;
    s.a = std::min(a, b);
    s.b = std::max(a, b);
    s.sites = {std::min(s0, s1), std::max(s0, s1), -1};
    return s;
}

RvdSymbol faceSymbol(int triangle, int s0, int s1, int s2)
{
    RvdSymbol s;
    s.kind = RvdVertexKind::FaceVoronoiEdge;
    s.a = triangle;
    s.sites = {s0, s1, s2};
    std::sort(s.sites.begin(), s.sites.end());
    return s;
}

RvdSymbol polygonVertexSymbol(const Triangle &tri, int t, int site, int in, int out)
{
    if (in < 0 && out < 0)
        return inputVertexSymbol(tri[rvd::inputEdgeOf(out)]);
    if (in < 0 || out < 0) {
        const int e = rvd::inputEdgeOf(in < 0 ? in : out);
        return edgeSymbol(tri[e], tri[(e + 1) % 3], site, in < 0 ? out : in);
    }
    return faceSymbol(t, site, in, out);
}

// Position of a symbolic vertex computed from its symbol only: bit-identical in every cell,
// triangle and line sharing it.
LocalVertex canonicalVertex(const RestrictionDomain &domain, const std::vector<Vec3> &sites,
                            const RvdSymbol &s)
{
    switch (s.kind) {
    case RvdVertexKind::InputVertex:
        return {s, domain.points[s.a], 0.0};
    case RvdVertexKind::EdgeBisector: {
        const rvd::ComputedPoint p =
            rvd::edgeVertexPoint(domain.points, sites, s.a, s.b, s.sites[0], s.sites[1]);
        return {s, p.position, p.error};
    }
    case RvdVertexKind::FaceVoronoiEdge: {
        const Triangle &t = domain.triangles[s.a];
        double u = 0, v = 0;
        const rvd::ComputedPoint p =
            rvd::faceVertexPoint(domain.points[t[0]], domain.points[t[1]], domain.points[t[2]],
                                 sites, s.sites[0], s.sites[1], s.sites[2], u, v);
        return {s, p.position, p.error};
    }
    }
    return {s, Vec3::Zero(), 0.0};
}

int chunks(std::size_t n)
{
    return static_cast<int>((n + kChunk - 1) / kChunk);
}

void checkCancel(const Progress &progress)
{
    if (progress.isCancelled())
        throw Cancelled();
}

} // namespace

std::string RvdSymbol::toString() const
{
    switch (kind) {
    case RvdVertexKind::InputVertex:
        return "point " + std::to_string(a);
    case RvdVertexKind::EdgeBisector:
        return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ") ∩ bisector("
               + std::to_string(sites[0]) + ", " + std::to_string(sites[1]) + ")";
    case RvdVertexKind::FaceVoronoiEdge:
        return "triangle " + std::to_string(a) + " ∩ Voronoi edge(" + std::to_string(sites[0])
               + ", " + std::to_string(sites[1]) + ", " + std::to_string(sites[2]) + ")";
    }
    return {};
}

std::size_t RvdSymbolHash::operator()(const RvdSymbol &s) const
{
    std::uint64_t h = static_cast<std::uint64_t>(s.kind) * 0x9E3779B97F4A7C15ull;
    for (int x : {s.a, s.b, s.sites[0], s.sites[1], s.sites[2]})
        h = (h ^ static_cast<std::uint32_t>(x)) * 0x100000001B3ull + (h >> 29);
    return static_cast<std::size_t>(h);
}

RestrictedVoronoiDiagram computeRestrictedVoronoi(const RestrictionDomain &domain,
                                                  const std::vector<Vec3> &sites,
                                                  Progress &progress, NeighbourSearch search)
{
    const VoronoiNeighbours delaunay(sites, search);
    progress.tick(0.1, "restricted Voronoi diagram");
    return computeRestrictedVoronoi(domain, delaunay, progress);
}

RestrictedVoronoiDiagram computeRestrictedVoronoi(const RestrictionDomain &domain,
                                                  const VoronoiNeighbours &delaunay,
                                                  Progress &progress)
{
    RestrictedVoronoiDiagram rvd;
    rvd.sites = delaunay.sites();
    const std::vector<Vec3> &sites = delaunay.sites();
    CellIntegralsWorkspace workspace;
    computePointOwners(domain, delaunay, workspace);
    const std::vector<int> &owners = workspace.pointOwners;
    progress.tick(0.2, "restricted Voronoi diagram");

    const int nt = static_cast<int>(domain.triangles.size());
    const int nseg = static_cast<int>(domain.segments.size());
    std::vector<Chunk> triangleChunks(chunks(nt)), segmentChunks(chunks(nseg));
    tbb::parallel_for(
        tbb::blocked_range<int>(0, chunks(nt), 1), [&](const tbb::blocked_range<int> &r) {
            rvd::CellClipper clipper(domain, delaunay);
            for (int c = r.begin(); c < r.end(); ++c) {
                checkCancel(progress);
                Chunk &out = triangleChunks[c];
                for (int t = c * kChunk; t < std::min(nt, (c + 1) * kChunk); ++t) {
                    const Triangle &tri = domain.triangles[t];
                    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
                        continue;
                    const int own[3] = {owners[tri[0]], owners[tri[1]], owners[tri[2]]};
                    clipper.forEachTrianglePart(
                        t, own, [&](int site, const rvd::ClipPolygon &poly) {
                            const rvd::PolygonIntegrals in = rvd::integratePolygon(poly, nullptr);
                            const int n = static_cast<int>(poly.size());
                            Vec3 centroid = sites[site] + in.firstMoment / in.area;
                            if (!(in.area > 0)) {
                                centroid = sites[site];
                                for (const rvd::ClipVertex &v : poly)
                                    centroid += v.position / n;
                            }
                            out.polygons.push_back({site, t, static_cast<int>(out.vertices.size()),
                                                    n, in.area, centroid});
                            for (int k = 0; k < n; ++k) {
                                const int inSupport = poly[(k + n - 1) % n].out;
                                out.vertices.push_back(
                                    polygonVertexSymbol(tri, t, site, inSupport, poly[k].out));
                                out.supports.push_back(poly[k].out);
                            }
                        });
                }
            }
        });
    progress.tick(0.6, "restricted Voronoi diagram");
    tbb::parallel_for(
        tbb::blocked_range<int>(0, chunks(nseg), 1), [&](const tbb::blocked_range<int> &r) {
            rvd::CellClipper clipper(domain, delaunay);
            for (int c = r.begin(); c < r.end(); ++c) {
                Chunk &out = segmentChunks[c];
                for (int s = c * kChunk; s < std::min(nseg, (c + 1) * kChunk); ++s) {
                    const auto &seg = domain.segments[s];
                    if (seg[0] == seg[1])
                        continue;
                    const int own[2] = {owners[seg[0]], owners[seg[1]]};
                    clipper.forEachSegmentPart(
                        s, own, [&](int site, const rvd::SegmentEnd &a, const rvd::SegmentEnd &b) {
                            LocalPiece piece{site, s, {}, (b.position - a.position).norm()};
                            const rvd::SegmentEnd *ends[2] = {&a, &b};
                            for (int e = 0; e < 2; ++e) {
                                const rvd::SegmentEnd &x = *ends[e];
                                const RvdSymbol sym =
                                    x.site < 0 ? inputVertexSymbol(seg[x.t == 0 ? 0 : 1])
                                               : edgeSymbol(seg[0], seg[1], site, x.site);
                                piece.ends[e] = sym;
                            }
                            out.pieces.push_back(piece);
                        });
                }
            }
        });
    progress.tick(0.7, "restricted Voronoi diagram");

    // Sequential merge in triangle order: vertex ids follow first appearance, deterministically.
    std::vector<int> pointVertex(domain.points.size(), -1);
    std::unordered_map<RvdSymbol, int, RvdSymbolHash> symbolVertex;
    const auto vertexId = [&](const RvdSymbol &symbol, int triangle) {
        int *slot = nullptr;
        if (symbol.kind == RvdVertexKind::InputVertex) {
            slot = &pointVertex[symbol.a];
        } else {
            const auto [it, inserted] = symbolVertex.emplace(symbol, -1);
            slot = &it->second;
        }
        if (*slot < 0) {
            *slot = static_cast<int>(rvd.vertices.size());
            const LocalVertex v = canonicalVertex(domain, sites, symbol);
            rvd.vertices.push_back({symbol, v.position, v.error, triangle,
                                    triangle >= 0 ? domain.triangleSurface[triangle] : -1});
        } else if (rvd.vertices[*slot].triangle < 0 && triangle >= 0) {
            rvd.vertices[*slot].triangle = triangle;
            rvd.vertices[*slot].surface = domain.triangleSurface[triangle];
        }
        return *slot;
    };
    for (const Chunk &c : triangleChunks) {
        for (const LocalPolygon &p : c.polygons) {
            RvdPolygon poly;
            poly.site = p.site;
            poly.triangle = p.triangle;
            poly.surface = domain.triangleSurface[p.triangle];
            poly.first = static_cast<int>(rvd.polygonVertices.size());
            poly.count = p.count;
            poly.area = p.area;
            poly.centroid = p.centroid;
            for (int k = 0; k < p.count; ++k) {
                rvd.polygonVertices.push_back(vertexId(c.vertices[p.first + k], p.triangle));
                rvd.polygonSupports.push_back(c.supports[p.first + k]);
            }
            rvd.polygons.push_back(poly);
        }
    }
    for (const Chunk &c : segmentChunks)
        for (const LocalPiece &p : c.pieces) {
            RvdLinePiece piece;
            piece.site = p.site;
            piece.segment = p.segment;
            piece.line = domain.segmentLine[p.segment];
            piece.length = p.length;
            for (int e = 0; e < 2; ++e)
                piece.vertices[e] = vertexId(p.ends[e], -1);
            rvd.linePieces.push_back(piece);
        }
    progress.tick(0.85, "restricted Voronoi diagram");

    // Vertex → polygons.
    rvd.vertexPolygonOffsets.assign(rvd.vertices.size() + 1, 0);
    for (int v : rvd.polygonVertices)
        ++rvd.vertexPolygonOffsets[v + 1];
    for (std::size_t v = 0; v < rvd.vertices.size(); ++v)
        rvd.vertexPolygonOffsets[v + 1] += rvd.vertexPolygonOffsets[v];
    rvd.vertexPolygons.resize(rvd.polygonVertices.size());
    {
        std::vector<int> fill(rvd.vertexPolygonOffsets.begin(), rvd.vertexPolygonOffsets.end() - 1);
        for (std::size_t p = 0; p < rvd.polygons.size(); ++p)
            for (int k = 0; k < rvd.polygons[p].count; ++k)
                rvd.vertexPolygons[fill[rvd.polygonVertices[rvd.polygons[p].first + k]]++] =
                    static_cast<int>(p);
    }

    rvd.cornerSites.resize(domain.corners.size());
    for (std::size_t c = 0; c < domain.corners.size(); ++c)
        rvd.cornerSites[c] = owners[domain.corners[c]];
    buildRestrictedCells(domain, rvd);
    progress.tick(1.0, "restricted Voronoi diagram");
    return rvd;
}

} // namespace stratamesh
