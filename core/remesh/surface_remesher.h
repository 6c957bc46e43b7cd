// Remeshing of all the surfaces of a structural model at once, at a chosen resolution, with
// topology control and simplification of the features below it (thesis chapter 4; Pellerin,
// Lévy, Caumon & Botella 2014, "Automatic surface remeshing of 3D structural models at specified
// resolution: A method based on Voronoi diagrams", Computers & Geosciences 62, 103–116).
//
//   thin strips removed whole (strip_collapse.h) → sites (Alg 4.1) → restricted Voronoi diagram
//   → cell components (Alg 4.3 step 1) → points (Alg 4.2, merges) → dual faces (Alg 4.3 step 3)
//   → fins along lines (line_fins.h) → post-processing (§4.4.5, Alg 4.4) → intersection repair
//   → new model (names kept, lines/corners/regions rebuilt) + ledger.
//
// The input is never changed; every simplification is a ledger record.
#pragma once

#include "common/progress.h"
#include "model/validity.h"
#include "remesh/dual_faces.h"
#include "remesh/duplicate_separation.h"
#include "remesh/intersection_repair.h"
#include "remesh/mesh_cleanup.h"
#include "remesh/simplification_ledger.h"
#include "remesh/thin_strips.h"

#include <vector>

namespace stratamesh {

// d_resolution's default: no close features are merged, and thin strips are removed as the strip
// factor says. An explicit d_resolution ≥ 0 also bounds the width of the strips removed, so 0
// asks for no simplification at all (issue 13). Any negative value means the default.
inline constexpr double kAutoDResolution = -1.0;

struct RemeshParams {
    int sites = 0;           // number of sites; when 0, derived from edgeLength
    double edgeLength = 0.0; // target edge length: sites = area / (√3/2 · L²), a hexagonal packing
    double dResolution = kAutoDResolution; // Alg 4.2 step 4; 0: nothing merged nor removed
    bool mergeAllExtraPoints = false;      // Alg 4.2 step 3 as in the thesis (see output_points.h)
    // Strips narrower than this fraction of the resolution edge length are removed whole before
    // remeshing (strip_collapse.h); 0 keeps them. A strip of width w holds one row of triangles of
    // base e with base angles atan(2w/e): 39° at 0.4, so narrower strips would only give slivers.
    double stripWidthFactor = 0.4;
    int iterations = 100;        // CVT iterations (thesis: 100)
    double boundaryWeight = 0.2; // α of F = (1 − α) F_CVT + α F_B (thesis §4.3.2)
    unsigned seed = 1;           // initial random sampling
    bool adaptive =
        false; // density ρ = (1 − d/d_max)^exponent from the distance d to corners (Fig 4.19)
    double adaptiveExponent = 4.0;
    double adaptiveFloor = 0.05; // smallest density, so that far surfaces still get sites
    // Feature sizing (feature_sizing.h): near two features that do not meet, cells are at most
    // lfsFactor times their distance, graded by sizingGradation, down to sizingMinFraction of the
    // edge length; the sites grow accordingly, to at most sizingMaxGrowth times those asked
    // (beyond, the smallest size is raised until they fit). 0 turns it off, the default: with
    // thin strips kept (stripWidthFactor 0) it keeps the topology of small throws (A2 at 5000
    // sites: 7 topology edits instead of 28) but takes about 3.5 times the sites and a lower
    // mean quality (0.857 instead of 0.861).
    double lfsFactor = 0.0;
    double sizingGradation = 0.4;
    double sizingMinFraction = 1.0 / 16.0;
    double sizingMaxGrowth = 4.0;
    CleanupParams cleanup;
    bool flips = true;       // quality-improving flips inside surfaces after the thesis steps
    int smoothingPasses = 3; // vertex relaxation on the input surfaces and lines (0: none)
    IntersectionRepairParams repair;
    // Local refinement (topology_refinement.h): rounds of more sites where the output is not
    // valid or its topology differs from the input's beyond d_resolution; 0 turns it off.
    // Up to 4 more rounds refine where the output is still not valid, beyond the growth cap.
    int refinementRounds = 4;
    double refinementDensityFactor = 2.0; // density raised this much around each place, per round
    int refinementIterations = 20;        // CVT iterations after sites are added
    // Rounds also pin sites on the corners and lines near each place, spaced by the local feature
    // size (featureSitesNearTargets), on a model split finer than that size there
    // (sizing_refinement.h), with graded free sites around them; the sites may then grow to
    // sizingMaxGrowth times those asked, and the quality limit below does not apply. Off by
    // default: modelA5 at 5000 sites with its strips kept goes from 90 topology edits to 11, but
    // from 5,000 to 20,573 sites and from 1.1 % to 2.7 % of triangles below 30°.
    bool refinementPinsFeatures = false;
    double refinementMaxGrowth =
        1.0; // topology places get at most this fraction of the asked sites
    // A round that only saves topology is kept when its share of triangles below 30° grows by at
    // most this many percentage points over the unrefined remesh (features far below the
    // resolution cannot be kept without needles). The first valid round over it is the last.
    double refinementMaxQualityLoss = 0.75;
};

struct RemeshTimings {
    double samplingSeconds = 0.0; // sampling + CVT optimisation
    double meshSeconds = 0.0;     // RVD, mesh building, post-processing, output model
    double totalSeconds = 0.0;
};

struct RemeshResult {
    Model model;                   // new model, with topology
    std::vector<ThinStrip> strips; // input strips removed whole
    SimplificationLedger ledger;
    std::vector<double> energy; // optimisation energy per iteration
    std::vector<Vec3> sites;    // optimised sites
    int siteCount = 0;
    RemeshTimings timings;
    DualFaceCounts faces;
    CleanupCounts cleanup;
    DuplicateSeparation duplicates;
    IntersectionRepairResult intersections;
    ValidityReport validity;  // of `model`; the front ends refuse to write an invalid one
    int initialSiteCount = 0; // the sites asked for; siteCount is the final number
    int sizedSiteCount = 0;   // the sites of the feature sizing field, before refinement rounds
    double smallestCellSize = 0.0; // the smallest size of the sizing field (the edge length
                                   // when nothing is refined)
    int refinementRounds = 0;      // rounds that added sites, up to the one kept
    int refinementRoundsRun = 0;   // rounds meshed, kept or not
    int remainingTargets = 0;      // places still wrong after the last round (0 when converged)
    int pocketsOpened = 0;         // pockets re-triangulated open (pocket_repair.h)
};

// Topology edits of a result per kind (surface, surface part, line and corner lost/created
// records).
struct TopologyEdits {
    int surfacesLost = 0, surfacesCreated = 0;
    int linesLost = 0, linesCreated = 0;
    int cornersLost = 0, cornersCreated = 0;
    int surfacePartsLost = 0, surfacePartsCreated = 0;
    int total() const
    {
        return surfacesLost + surfacesCreated + linesLost + linesCreated + cornersLost
               + cornersCreated + surfacePartsLost + surfacePartsCreated;
    }
};
TopologyEdits countTopologyEdits(const SimplificationLedger &ledger);

// The distance below which parts of features are merged (Alg 4.2 step 4): d_resolution, 0 when
// it is the default.
double mergeDistance(const RemeshParams &params);
// The widest thin strip removed before remeshing at this edge length: the strip factor times it,
// bounded by an explicit d_resolution.
double stripWidthLimit(const RemeshParams &params, double edgeLength);
// Whether refinement pins sites on the features (refinementPinsFeatures): asked for, or implied
// by d_resolution 0, which asks to keep every feature (without pins, 19 of the 24 runs of the
// test matrix ended with topology edits, 2,815 in all, and network5 at 1000 sites not valid;
// with them, 9 of 24 runs kept everything, 248 edits in all, every run valid).
bool pinsFeatures(const RemeshParams &params);

// The fewest and most sites a remesh takes: the range of the `sites` entry of
// remeshParamTable() (params/param_tables.h), which every front end and check reads.
inline constexpr int kMinRemeshSites = 4;
inline constexpr int kMaxRemeshSites = 10000000;
// d_resolution above this fraction of the bounding-box diagonal would merge features across the
// model: refused.
inline constexpr double kMaxDResolutionFraction = 0.1;

// Number of sites for a target edge length over a total surface area (at least the `sites`
// minimum). Throws
// InputError when the edge length is not positive or gives more than kMaxRemeshSites.
int sitesForEdgeLength(double area, double edgeLength);
// Its inverse: the edge length of a hexagonal packing of `sites` points over `area`.
double edgeLengthForSites(double area, int sites);
// The total area of the model's surfaces, which the sites cover (box surfaces included).
double modelArea(const Model &model);

// Throws InputError on parameters outside their ranges (remeshParamTable()) or that make no
// sense for this model, on an empty model; Cancelled when cancelled.
RemeshResult remeshModel(const Model &input, const RemeshParams &params,
                         Progress &progress = Progress::none());

// The mesh-building half alone, from given sites (tests and benchmarks): `input` with topology.
RemeshResult remeshWithSites(const Model &input, const std::vector<Vec3> &sites,
                             const RemeshParams &params, Progress &progress = Progress::none());

} // namespace stratamesh
