// Connected components of the restricted Voronoi cells (thesis §4.4, Algorithm 4.3 step 1, and
// Fig 4.4–4.6). For each site:
//  - surface pieces: facets of the site on one surface joined across input edges that are not
//    on a line (a line cuts a surface piece, since the output must keep the line);
//  - line components ("BC" in Algorithm 4.2): line pieces of the site joined at shared points,
//    across corners too;
//  - cell components ("CC"): surface pieces and line components joined where a piece runs along
//    a line inside the cell.
// Connectivity is decided on symbolic vertices and input edge ids only.
#pragma once

#include "voronoi/restricted_voronoi.h"

#include <vector>

namespace stratamesh {

struct CellComponents {
    // Surface pieces.
    std::vector<int> facetPiece; // facet → piece
    std::vector<int> pieceSite;
    std::vector<int> pieceSurface;
    std::vector<std::vector<int>> pieceLineComponents; // line components each piece runs along
    // Line components.
    std::vector<int> linePieceComponent; // line piece → line component
    std::vector<int> lineComponentSite;
    std::vector<std::vector<int>> lineComponentCorners; // domain corners inside each
    std::vector<std::vector<int>> lineComponentPieces;  // its line pieces
    // Cell components over both.
    std::vector<int> pieceCell;         // piece → cell component
    std::vector<int> lineComponentCell; // line component → cell component
    std::vector<int> cellSite;
    std::vector<std::vector<int>> cellPieces;
    std::vector<std::vector<int>> cellLineComponents;

    // Line piece of (segment, site), or -1.
    int linePieceOf(int segment, int site) const;
    std::vector<std::vector<std::pair<int, int>>> segmentPieces; // per segment: (site, line piece)
};

CellComponents computeCellComponents(const RestrictionDomain &domain,
                                     const RestrictedVoronoiDiagram &cells);

// Domain segment joining two domain points, or -1 (built once per domain).
class SegmentIndex {
public:
    explicit SegmentIndex(const RestrictionDomain &domain);
    int find(int p, int q) const;

private:
    std::vector<std::vector<std::pair<int, int>>> m_byPoint; // point → (other point, segment)
};

} // namespace stratamesh
