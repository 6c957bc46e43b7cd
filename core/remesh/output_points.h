// Output mesh vertices from the restricted Voronoi cells, thesis §4.4.2–4.4.3, Algorithm 4.2:
//  (1) per cell component, one point per corner it contains, else one per line component it
//      touches (placed on that line), else one at its centroid projected onto the input surface;
//  (2) corners of one cell joined by a line are merged (Fig 4.6b);
//  (3) a cell component with more than two points has them merged (Fig 4.6a) — all of them, or
//      by default only the closest until two are left;
//  (4) points of one cell whose model parts are closer than d_resolution are merged (Fig 4.7:
//      cancels small fault throws, joins close surfaces); d_resolution = 0 disables it.
// Every merge is a ledger record naming the input surfaces, lines and corners involved.
#pragma once

#include "common/progress.h"

#include "remesh/cell_components.h"
#include "remesh/output_mesh.h"
#include "remesh/simplification_ledger.h"

namespace stratamesh {

struct CellPoints {
    std::vector<OutputPoint> points;
    std::vector<int> lineComponentPoint;       // line component → point
    std::vector<int> cellPoint;                // cell component → its point when it has one only
    std::vector<std::vector<int>> piecePoints; // surface piece → its distinct points (1 or 2)
};

struct CellPointsParams {
    double dResolution = 0.0; // step (4); 0 disables it
    // Step (3) as in the thesis (all points of the component merged into one) when true; else
    // the two points with the closest model parts are merged until two are left, which keeps
    // more of the model (e.g. a fault throw whose two contacts are farther apart than others).
    bool mergeAllExtraPoints = false;
};

// `model` is the input the domain was made from (names for the ledger; line incidences).
CellPoints computeCellPoints(const Model &model, const RestrictionDomain &domain,
                             const RestrictedVoronoiDiagram &cells,
                             const CellComponents &components, const CellPointsParams &params,
                             SimplificationLedger &ledger, Progress &progress = Progress::none());

} // namespace stratamesh
