// TetGen comparison meshes of a model (thesis §5.2: what a volume mesher makes of the input model
// and of its remesh), crash-proof: TetGen 1.5 (Si 2015, ACM TOMS 41(2)) runs in the helper process
// stratamesh-tetgen (app/tetgen_runner) under a time and a memory limit, and every way it can end
// becomes a TetgenOutcome. The model is checked first for what makes TetGen crash or abort:
// intersecting surfaces, one triangle on two surfaces, and points close enough for TetGen to merge
// them (formats.md §4.5; model/validity.h).
#pragma once

#include "common/progress.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <functional>
#include <string>
#include <vector>

namespace stratamesh {

enum class TetgenOutcome { Ok, Aborted, TimedOut, OutOfMemory, Killed, InvalidInput };

// "ok", "aborted", "timed_out", "out_of_memory", "killed", "invalid_input".
const char *tetgenOutcomeName(TetgenOutcome outcome);

struct TetgenParams {
    double quality = 1.414;      // radius-edge ratio bound (q); 0 = no quality refinement
    double maxVolume = 0.0;      // maximum tet volume (a); 0 = none
    bool refineSurfaces = false; // let TetGen add points on the surfaces (drops Y)
    // M: without Y, TetGen merges nearly coplanar facets and re-triangulates them, which moves
    // region volumes by ~1e-6 (modelA1); M keeps them exact but refines far more (×9 tets on A1).
    bool noMerge = false;
    double timeLimitSeconds = 0.0; // 0 = none
    double memoryLimitMB = 0.0;    // address space of the helper; 0 = none
    bool checkInput = true;        // the validity check before TetGen (off only to test TetGen)
    std::string helperPath;        // empty: findTetgenHelper()
    std::function<void(int pid)> onStarted; // receives the helper's pid (tests kill it)
};

struct TetgenResult {
    TetgenOutcome outcome = TetgenOutcome::Aborted;
    std::string message;               // one line for the user; empty when ok
    std::string lastOutput;            // TetGen's (or the helper's) last output line
    std::vector<std::string> surfaces; // invalid_input: the surfaces involved
    std::string switches;
    double seconds = 0.0; // wall time of the helper
    int exitCode = -1;    // of the helper, when it exited
    int signal = 0;       // that ended it, when one did

    // When ok: tets (positively oriented) with their region (index in Model::regions), boundary
    // and interface triangles with their surface, region and surface names of the model.
    VolumeMesh mesh;
    std::size_t tetsLocatedByCentroid = 0; // attribute 0, or a subdomain without a seed
    std::size_t tetsWithoutRegion = 0;     // centroid in no region (cellRegion -1)
};

// "pq1.414AY" by default: p PLC, q quality, a max volume, A region attributes, Y keep surfaces,
// M no merge of coplanar facets.
std::string tetgenSwitches(const TetgenParams &params);

// The helper: STRATAMESH_TETGEN_HELPER, else stratamesh-tetgen beside the running executable or
// in ../bin from it, else its build-tree path. Empty when none is executable.
std::string findTetgenHelper();

// Throws Cancelled (after killing and reaping the helper) when progress is cancelled, InputError
// for negative or NaN parameters; every other failure is a result with its outcome (a model
// whose topology cannot be recovered is invalid_input, a work folder that cannot be written is
// aborted).
TetgenResult runTetgen(const Model &model, const TetgenParams &params,
                       Progress &progress = Progress::none());

// As above, with TetGen's hole points (Plc::holes): the subdomains holding one stay empty.
TetgenResult runTetgen(const Model &model, const std::vector<Vec3> &holes,
                       const TetgenParams &params, Progress &progress = Progress::none());

} // namespace stratamesh
