#include "remesh/cell_components.h"

#include "common/union_find.h"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace stratamesh {

namespace {

std::uint64_t pairKey(int a, int b)
{
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32)
           | static_cast<std::uint32_t>(b);
}

void sortUnique(std::vector<int> &v)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

} // namespace

SegmentIndex::SegmentIndex(const RestrictionDomain &domain) : m_byPoint(domain.points.size())
{
    for (int s = 0; s < static_cast<int>(domain.segments.size()); ++s) {
        const auto &seg = domain.segments[s];
        m_byPoint[seg[0]].push_back({seg[1], s});
        m_byPoint[seg[1]].push_back({seg[0], s});
    }
}

int SegmentIndex::find(int p, int q) const
{
    for (const auto &[other, s] : m_byPoint[p])
        if (other == q)
            return s;
    return -1;
}

int CellComponents::linePieceOf(int segment, int site) const
{
    if (segment < 0 || segment >= static_cast<int>(segmentPieces.size()))
        return -1;
    for (const auto &[s, piece] : segmentPieces[segment])
        if (s == site)
            return piece;
    return -1;
}

CellComponents computeCellComponents(const RestrictionDomain &domain,
                                     const RestrictedVoronoiDiagram &cells)
{
    CellComponents cc;
    const SegmentIndex segments(domain);
    const int nf = static_cast<int>(cells.polygons.size());

    // Surface pieces: facets of one site joined across input edges off the lines.
    UnionFind facetsUf(nf);
    std::unordered_map<std::uint64_t, int> byEdgeAndSite;
    byEdgeAndSite.reserve(2 * nf);
    for (int f = 0; f < nf; ++f) {
        const RvdPolygon &facet = cells.polygons[f];
        const Triangle &tri = domain.triangles[facet.triangle];
        for (int k = 0; k < facet.count; ++k) {
            const int support = cells.polygonSupports[facet.first + k];
            if (support >= 0)
                continue;
            const int e = -1 - support;
            if (segments.find(tri[e], tri[(e + 1) % 3]) >= 0)
                continue;
            const int edgeId = domain.edgeIds[3 * facet.triangle + e];
            auto [it, inserted] = byEdgeAndSite.emplace(pairKey(edgeId, facet.site), f);
            if (!inserted)
                facetsUf.join(f, it->second);
        }
    }
    int pieceCount = 0;
    cc.facetPiece = facetsUf.labels(pieceCount);
    cc.pieceSite.assign(pieceCount, -1);
    cc.pieceSurface.assign(pieceCount, -1);
    for (int f = 0; f < nf; ++f) {
        cc.pieceSite[cc.facetPiece[f]] = cells.polygons[f].site;
        cc.pieceSurface[cc.facetPiece[f]] = domain.triangleSurface[cells.polygons[f].triangle];
    }

    // Line components: line pieces of one site sharing an end.
    const int nl = static_cast<int>(cells.linePieces.size());
    cc.segmentPieces.assign(domain.segments.size(), {});
    UnionFind linesUf(nl);
    std::unordered_map<std::uint64_t, int> byEndAndSite;
    for (int l = 0; l < nl; ++l) {
        const RvdLinePiece &piece = cells.linePieces[l];
        cc.segmentPieces[piece.segment].push_back({piece.site, l});
        for (int v : {piece.vertices[0], piece.vertices[1]}) {
            auto [it, inserted] = byEndAndSite.emplace(pairKey(v, piece.site), l);
            if (!inserted)
                linesUf.join(l, it->second);
        }
    }
    int lineComponentCount = 0;
    cc.linePieceComponent = linesUf.labels(lineComponentCount);
    cc.lineComponentSite.assign(lineComponentCount, -1);
    cc.lineComponentPieces.assign(lineComponentCount, {});
    cc.lineComponentCorners.assign(lineComponentCount, {});
    for (int l = 0; l < nl; ++l) {
        cc.lineComponentSite[cc.linePieceComponent[l]] = cells.linePieces[l].site;
        cc.lineComponentPieces[cc.linePieceComponent[l]].push_back(l);
    }
    std::unordered_map<int, int> inputVertexOfPoint;
    for (int v = 0; v < static_cast<int>(cells.vertices.size()); ++v)
        if (cells.vertices[v].symbol.kind == RvdVertexKind::InputVertex)
            inputVertexOfPoint[cells.vertices[v].symbol.a] = v;
    for (int c = 0; c < static_cast<int>(domain.corners.size()); ++c) {
        auto it = inputVertexOfPoint.find(domain.corners[c]);
        if (it == inputVertexOfPoint.end())
            continue;
        auto piece = byEndAndSite.find(pairKey(it->second, cells.cornerSites[c]));
        if (piece != byEndAndSite.end())
            cc.lineComponentCorners[cc.linePieceComponent[piece->second]].push_back(c);
    }

    // Pieces running along lines, and cell components.
    cc.pieceLineComponents.assign(pieceCount, {});
    for (int f = 0; f < nf; ++f) {
        const RvdPolygon &facet = cells.polygons[f];
        const Triangle &tri = domain.triangles[facet.triangle];
        for (int k = 0; k < facet.count; ++k) {
            const int support = cells.polygonSupports[facet.first + k];
            if (support >= 0)
                continue;
            const int e = -1 - support;
            const int s = segments.find(tri[e], tri[(e + 1) % 3]);
            const int l = s >= 0 ? cc.linePieceOf(s, facet.site) : -1;
            if (l >= 0)
                cc.pieceLineComponents[cc.facetPiece[f]].push_back(cc.linePieceComponent[l]);
        }
    }
    UnionFind cellUf(pieceCount + lineComponentCount);
    for (int p = 0; p < pieceCount; ++p) {
        sortUnique(cc.pieceLineComponents[p]);
        for (int b : cc.pieceLineComponents[p])
            cellUf.join(p, pieceCount + b);
    }
    int cellCount = 0;
    const std::vector<int> label = cellUf.labels(cellCount);
    cc.cellSite.assign(cellCount, -1);
    cc.cellPieces.assign(cellCount, {});
    cc.cellLineComponents.assign(cellCount, {});
    cc.pieceCell.assign(pieceCount, -1);
    cc.lineComponentCell.assign(lineComponentCount, -1);
    for (int p = 0; p < pieceCount; ++p) {
        cc.pieceCell[p] = label[p];
        cc.cellSite[label[p]] = cc.pieceSite[p];
        cc.cellPieces[label[p]].push_back(p);
    }
    for (int b = 0; b < lineComponentCount; ++b) {
        const int c = label[pieceCount + b];
        cc.lineComponentCell[b] = c;
        cc.cellSite[c] = cc.lineComponentSite[b];
        cc.cellLineComponents[c].push_back(b);
    }
    return cc;
}

} // namespace stratamesh
