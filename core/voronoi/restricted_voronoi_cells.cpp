#include "voronoi/restricted_voronoi_cells.h"

#include "common/union_find.h"

#include <algorithm>

namespace stratamesh {
namespace {

void surfaceComponents(const RestrictionDomain &domain, RestrictedVoronoiDiagram &rvd)
{
    const int np = static_cast<int>(rvd.polygons.size());
    const int nt = static_cast<int>(domain.triangles.size());
    UnionFind uf(np);
    // Polygons are grouped by triangle; triangles sharing a surface edge, by edge id.
    std::vector<int> triangleFirst(nt + 1, 0);
    for (const RvdPolygon &p : rvd.polygons)
        ++triangleFirst[p.triangle + 1];
    for (int t = 0; t < nt; ++t)
        triangleFirst[t + 1] += triangleFirst[t];
    const int ne = domain.edgeIds.empty()
                       ? 0
                       : *std::max_element(domain.edgeIds.begin(), domain.edgeIds.end()) + 1;
    std::vector<int> edgeFirst(ne + 1, 0), edgeTriangles(domain.edgeIds.size());
    for (int id : domain.edgeIds)
        ++edgeFirst[id + 1];
    for (int e = 0; e < ne; ++e)
        edgeFirst[e + 1] += edgeFirst[e];
    {
        std::vector<int> fill(edgeFirst.begin(), edgeFirst.end() - 1);
        for (std::size_t k = 0; k < domain.edgeIds.size(); ++k)
            edgeTriangles[fill[domain.edgeIds[k]]++] = static_cast<int>(k / 3);
    }
    for (int p = 0; p < np; ++p) {
        const RvdPolygon &poly = rvd.polygons[p];
        const int *supports = rvd.polygonSupportsBegin(p);
        for (int k = 0; k < poly.count; ++k) {
            if (supports[k] >= 0)
                continue;
            const int edge = domain.edgeIds[3 * poly.triangle + (-1 - supports[k])];
            for (int q = edgeFirst[edge]; q < edgeFirst[edge + 1]; ++q) {
                const int t2 = edgeTriangles[q];
                if (t2 <= poly.triangle)
                    continue; // each pair of triangles once
                for (int p2 = triangleFirst[t2]; p2 < triangleFirst[t2 + 1]; ++p2)
                    // The cell meets both sides of the edge: along it (convexity).
                    if (rvd.polygons[p2].site == poly.site)
                        uf.join(p, p2);
            }
        }
    }
    std::vector<int> componentOfRoot(np, -1);
    for (int p = 0; p < np; ++p) {
        RvdPolygon &poly = rvd.polygons[p];
        const int root = uf.find(p);
        if (componentOfRoot[root] < 0) {
            componentOfRoot[root] = static_cast<int>(rvd.surfaceComponents.size());
            RvdSurfaceComponent c;
            c.site = poly.site;
            c.surface = poly.surface;
            rvd.surfaceComponents.push_back(c);
        }
        RvdSurfaceComponent &c = rvd.surfaceComponents[componentOfRoot[root]];
        poly.component = componentOfRoot[root];
        c.polygons.push_back(p);
        c.area += poly.area;
        c.centroid += poly.area * poly.centroid;
    }
    for (RvdSurfaceComponent &c : rvd.surfaceComponents) {
        if (c.area > 0) {
            c.centroid /= c.area;
        } else {
            c.centroid.setZero();
            for (int p : c.polygons)
                c.centroid += rvd.polygons[p].centroid / static_cast<double>(c.polygons.size());
        }
    }
}

void lineComponents(const RestrictionDomain &domain, RestrictedVoronoiDiagram &rvd)
{
    const int nseg = static_cast<int>(domain.segments.size());
    std::vector<int> firstPiece(nseg + 1, 0);
    for (const RvdLinePiece &piece : rvd.linePieces)
        ++firstPiece[piece.segment + 1];
    for (int s = 0; s < nseg; ++s)
        firstPiece[s + 1] += firstPiece[s];
    for (int line = 0; line < domain.lineCount; ++line) {
        std::vector<int> order; // pieces along the line
        for (int k = domain.lineOffsets[line]; k < domain.lineOffsets[line + 1]; ++k) {
            const int s = domain.lineSegments[k];
            for (int p = firstPiece[s]; p < firstPiece[s + 1]; ++p)
                order.push_back(p);
        }
        if (order.empty())
            continue;
        // Runs of one site; a closed line joins its last run to its first.
        std::vector<std::vector<int>> runs;
        for (int p : order) {
            if (runs.empty() || rvd.linePieces[runs.back().back()].site != rvd.linePieces[p].site)
                runs.emplace_back();
            runs.back().push_back(p);
        }
        const bool closed = domain.lineClosed[line] != 0;
        bool wholeLoop = closed && runs.size() == 1;
        if (closed && runs.size() > 1
            && rvd.linePieces[runs.front().front()].site
                   == rvd.linePieces[runs.back().back()].site) {
            runs.back().insert(runs.back().end(), runs.front().begin(), runs.front().end());
            runs.erase(runs.begin());
        }
        for (const std::vector<int> &run : runs) {
            RvdLineComponent c;
            c.site = rvd.linePieces[run.front()].site;
            c.line = line;
            c.pieces = run;
            if (!wholeLoop)
                c.ends = {rvd.linePieces[run.front()].vertices[0],
                          rvd.linePieces[run.back()].vertices[1]};
            for (int p : run) {
                const RvdLinePiece &piece = rvd.linePieces[p];
                c.length += piece.length;
                c.centroid += piece.length * 0.5
                              * (rvd.vertices[piece.vertices[0]].position
                                 + rvd.vertices[piece.vertices[1]].position);
            }
            if (c.length > 0)
                c.centroid /= c.length;
            else
                c.centroid = rvd.vertices[rvd.linePieces[run.front()].vertices[0]].position;
            for (int p : run)
                rvd.linePieces[p].component = static_cast<int>(rvd.lineComponents.size());
            rvd.lineComponents.push_back(std::move(c));
        }
    }
}

} // namespace

void buildRestrictedCells(const RestrictionDomain &domain, RestrictedVoronoiDiagram &rvd)
{
    rvd.surfaceComponents.clear();
    rvd.lineComponents.clear();
    surfaceComponents(domain, rvd);
    lineComponents(domain, rvd);
    rvd.cells.assign(rvd.sites.size(), RestrictedCell{});
    for (std::size_t c = 0; c < rvd.surfaceComponents.size(); ++c) {
        const RvdSurfaceComponent &comp = rvd.surfaceComponents[c];
        RestrictedCell &cell = rvd.cells[comp.site];
        cell.surfaceComponents.push_back(static_cast<int>(c));
        cell.area += comp.area;
        cell.centroid += comp.area * comp.centroid;
    }
    for (std::size_t c = 0; c < rvd.lineComponents.size(); ++c) {
        RestrictedCell &cell = rvd.cells[rvd.lineComponents[c].site];
        cell.lineComponents.push_back(static_cast<int>(c));
        cell.length += rvd.lineComponents[c].length;
    }
    for (std::size_t s = 0; s < rvd.cells.size(); ++s) {
        RestrictedCell &cell = rvd.cells[s];
        cell.centroid = cell.area > 0 ? Vec3(cell.centroid / cell.area) : rvd.sites[s];
    }
    for (std::size_t c = 0; c < rvd.cornerSites.size(); ++c)
        if (rvd.cornerSites[c] >= 0)
            rvd.cells[rvd.cornerSites[c]].corners.push_back(static_cast<int>(c));
}

} // namespace stratamesh
