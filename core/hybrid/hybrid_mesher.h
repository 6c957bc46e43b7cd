// Hybrid tet/prism/pyramid meshes of a structural model (thesis chapter 5; Pellerin et al. 2012,
// IMR research note "Toward mixed-element meshing based on restricted Voronoi diagrams"), made
// valid every time:
//   volumetric CVT of the model's bounding box (§5.2) → surfaces remeshed from those sites
//   (chapter 4, one point per restricted-cell component, no flips or smoothing so that triangles
//   stay dual to restricted Voronoi vertices) → segment-dual cells in thin layers (§5.3.2) and
//   vertex-dual tets where four Voronoi cells meet away from the surfaces (§5.3.3) →
//   transition pyramids on their quad faces that face the rest of the region → the rest of each
//   region filled with tets by TetGen (out of process), constrained to the remesh and to the
//   triangle faces of the cells, with a hole point in every cell so that TetGen leaves their
//   zones empty → mixed-mesh check; cells found invalid are removed and the cavity
//   refilled (repair rounds), down to the plain TetGen mesh of the remesh as the last resort.
// Vertex-dual cells at Voronoi vertices whose cells are cut by surfaces are tets when each cell
// part gives one point (Fig 5.4 with 4 vertices); the 5–8-vertex cells and the splits of §5.4
// are not built: TetGen's tets stand in for them (counted as fill tets).
#pragma once

#include "common/progress.h"
#include "hybrid/mixed_mesh_validity.h"
#include "hybrid/segment_dual_cells.h"
#include "hybrid/vertex_dual_cells.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"
#include "volume/tetgen_runner.h"

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace stratamesh {

struct HybridParams {
    int sites = 1000;
    int cvtIterations = 30;
    // §5.2: Lloyd steps of the sites meeting a surface, on the surfaces; they make the Voronoi
    // edges across thin layers that give prisms (modelA1@1000: 64 prisms without, 258 with 10).
    int surfaceIterations = 10;
    unsigned seed = 1;
    SegmentDualParams cells;
    VertexDualParams vertexCells;
    double pyramidHeightRatio = 0.15; // apex height over the square root of the quad area
    int repairRounds = 4;
    TetgenParams tetgen; // pq1.414AY by default
    // When set, the PLC of the first fill (cavity facets and hole points) is written there as a
    // TetGen .poly, to check it with `tetgen -d` outside StrataMesh.
    std::string cavityPolyPath;
};

struct HybridTimings {
    double cvtSeconds = 0.0, surfaceSitesSeconds = 0.0, remeshSeconds = 0.0, cellsSeconds = 0.0,
           fillSeconds = 0.0, checkSeconds = 0.0, totalSeconds = 0.0;
};

struct HybridResult {
    VolumeMesh mesh;                    // empty cells when no valid mesh could be made
    MixedMeshValidity validity;         // of mesh
    SegmentDualCells segmentDual;       // candidates and rejections of §5.3.2
    VertexDualCells vertexDual;         // candidates and rejections of §5.3.3
    std::size_t segmentDualKept = 0;    // segment-dual cells in the final mesh
    std::size_t vertexDualKept = 0;     // vertex-dual tets in the final mesh
    std::size_t cutVertexDualKept = 0;  // of which at cut Voronoi vertices (cut_vertex_cells.h)
    std::size_t transitionPyramids = 0; // pyramids on quads facing the tets
    std::size_t loweredPyramids = 0;    // of which lowered not to cross a neighbouring facet
    std::size_t fillTets = 0;           // tets from TetGen
    std::size_t invalidFound = 0;       // cells rejected or found invalid (shape, check, TetGen)
    std::size_t repaired = 0;           // thesis cells removed and their place refilled
    int repairRounds = 0;               // fills after the first
    bool fellBackToTetgen = false;      // the last resort: no hybrid cell at all
    int remeshSites = 0;
    bool remeshValid = false;
    // The surfaces the cells stand on (§5.2: one point per restricted-cell component), so that a
    // TetGen mesh of the very same surfaces can be compared with the hybrid one.
    std::shared_ptr<const Model> surfaceRemesh;
    std::map<std::string, std::size_t> remeshProblems; // check -> count, when not valid
    // The dual remesh (no flips, smoothing or refinement) was not valid, and the surfaces are the
    // chapter-4 remesh of the same sites; what the first one had.
    bool remeshRetried = false;
    std::map<std::string, std::size_t> firstRemeshProblems;
    TetgenOutcome tetgenOutcome = TetgenOutcome::Aborted;
    std::string message;                // why the mesh is empty or not valid
    std::vector<std::string> repairLog; // per fill that was not kept: what was wrong, cells dropped
    HybridTimings timings;
};

// Throws InputError for sites < 4 or a model without surfaces, Cancelled when cancelled.
HybridResult buildHybridMesh(const Model &model, const HybridParams &params,
                             Progress &progress = Progress::none());

} // namespace stratamesh
