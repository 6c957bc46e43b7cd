// Post-processing of the output mesh, thesis §4.4.5 (Pellerin et al. 2014, Computers &
// Geosciences 62, §4.5): tiny restricted Voronoi cell components give valence-3 vertices inside
// surfaces (Fig 4.8a), degenerate triangles on free borders (Fig 4.8b) and along contacts
// (Fig 4.9). Each removal is a ledger record.
//
// Algorithm 4.4 classifies the vertices of a degenerate triangle along a contact (4 = dual of a
// tiny cell, 1 = on the contact) and either merges its two off-contact vertices (configuration
// 9 = 4+4+1, Fig 4.9c) or inserts the off-contact vertex into the contact edge (configuration
// 6 = 4+1+1, Fig 4.9d). We apply the same two operations from the triangle's shape, which does
// not need the cells any more: a needle (short edge) is collapsed, a cap (an apex close to the
// opposite edge) has that edge split by its apex in every surface along it — so the contact
// stays sealed — or flipped when the edge is inside one surface.
#pragma once

#include "remesh/editable_soup.h"
#include "remesh/simplification_ledger.h"

namespace stratamesh {

struct CleanupParams {
    double degenerateQuality = 0.15; // triangles below this Q are degenerate
    double capAngleDeg = 120.0;      // an apex angle above this makes a cap, else a needle
    int maxPasses = 10;
};

struct CleanupCounts {
    int lineFins = 0; // line_fins.h
    int valence3 = 0;
    int borderTriangles = 0;
    int contactTriangles = 0;
    int interiorCollapses = 0;
    int flips = 0;
    int relaxed = 0;   // vertex moves of the relaxation (mesh_smoothing.h)
    int stripRows = 0; // vertices added down the middle of strips (strip_rows.h)
};

// The input model gives names to the ledger records (point.surfaces/lines/corners index it).
CleanupCounts removeValence3Vertices(EditableSoup &soup, const Model &input,
                                     SimplificationLedger &ledger);
CleanupCounts removeDegenerateTriangles(EditableSoup &soup, const Model &input,
                                        const CleanupParams &params, SimplificationLedger &ledger);
// Flips interior edges of one surface while the smaller quality of the pair improves.
int improveByFlips(EditableSoup &soup, int maxPasses = 5);

// Input entities a set of output points samples, for ledger records.
std::vector<EntityRef> inputEntitiesOf(const EditableSoup &soup, const Model &input,
                                       const std::vector<int> &points);

} // namespace stratamesh
