// The stratamesh-cli command registry: main.cpp builds dispatch and --help from this one list.
//
// To add a command `foo` (three small edits, nothing else to touch):
//   1. write app/cli/command_foo.cpp defining
//          namespace stratamesh::cli { int runFoo(CommandArgs &args) { ... } }
//      read options first (args.flag("--json"), args.option("--out")...), then positionals, then
//      call args.finish(); return 0 on success. Throw UsageError for a bad command line and let
//      core errors (FileError, InputError, Cancelled) propagate: main prints them and exits 1.
//      Helpers: cli_output.h (printJson, out), json_report.h and param_json.h
//      (app/report: core results and parameters as JSON).
//   2. add command_foo.cpp to app/cli/CMakeLists.txt;
//   3. add ONE line to the list below:  X("foo", runFoo, "ARGUMENTS", "One-line summary") \.
// A command whose parameters have a table in core/params names it in command_params.cpp, reads
// them with args.params(table, params) and writes "{params}" in ARGUMENTS where its usage line
// lists them: flags, usage, --help, range checks and the README list then follow the table.
#pragma once

#include "command_args.h"

#include <vector>

// clang-format off
#define STRATAMESH_CLI_COMMANDS(X)                                                                 \
    X("info", runInfo, "MODEL [--json]", "Counts, mesh statistics, region volumes and validity of a model") \
    X("remesh", runRemesh, "MODEL (--sites N | --edge-length L) {params} [--allow-invalid] [--params REPORT.json] -o OUT.(ml|ts|gm|msh|vtu|vtk|vtp) [--report REPORT.json] [--overwrite]", "Remesh all surfaces at a resolution, refined locally until valid; features closer than d_resolution are merged and thin strips narrower than it and than the strip factor times the edge length (default 0.4) removed, each with a ledger record; d_resolution 0 simplifies nothing and pins sites on the close features, the default (-1, Auto) merges nothing and removes strips by the strip factor alone (thesis ch. 4)") \
    X("convert", runConvert, "IN OUT [--msh-version 4.1|2.2] [--save-all] [--surface N] [--json] [--overwrite]", "Convert between Gocad (.ml .ts .so), RINGMesh (.gm), VTK (.vtu .vtk .vtp), Gmsh (.msh) and single-surface (.obj .off .stl .ply) files, formats from the extensions") \
    X("cvt", runCvt, "MODEL --sites N [--seed S] {params} [--json] [--sites-out FILE.xyz] [--neighbours delaunay|nearest] [--overwrite]", "Optimise N sites over all surfaces and lines (CVT + boundary energy, L-BFGS); RDT quality and timings (thesis §4.3)") \
    X("complexity", runComplexity, "MODEL {params} [--json] [--cells-vtk OUT.vtu] [--overwrite]", "Complexity measures of thesis ch. 3 (box excluded): counts, geometric complexity, size variation, elements per Voronoi cell (Tables 3.1-3.4)") \
    X("synthetic", runSynthetic, "(layered|network|spheres|sample) [--faults 3] [--dip 30] [--horizons 3] [--throw 20] [--edge-length 40] [--thin-layer 0] [--inner-radius 1] [--middle-radius 0] [--outer-radius 2] -o OUT [--overwrite]", "Write a model built in code: a layered box, a low-dip fault network (throws 0.3, 1.5, 0.6, 2.5 x --throw), nested spheres, the sample") \
    X("tetmesh", runTetmesh, "MODEL {params} [-o OUT.(vtu|vtk|msh|so)] [--msh-version 4.1|2.2] [--report R.json] [--json] [--poly PLC.poly] [--overwrite]", "TetGen comparison mesh in a helper process (thesis §5.2): tets per region, dihedral angles, slivers, outcome (ok, aborted, timed_out, out_of_memory, killed, invalid_input)") \
    X("study", runStudy, "STUDY.smstudy (--plan | --run [--jobs N] | --task ID | --gather | --status | --submit slurm [--partition P] [--time T] [--mem M] [--max-parallel K] | --resubmit-failed [same options]) [--json]", "Many models x many parameter sets: plan, run here (resumable) or as one Slurm job array, gather one table of every task") \
    X("hybrid", runHybrid, "MODEL {params} [-o OUT.(vtu|msh)] [--report R.json] [--json] [--cavity-poly PLC.poly] [--surface-remesh S.ml] [--overwrite]", "Hybrid tet/prism/pyramid mesh from one Voronoi diagram, prisms in thin layers, checked valid (thesis ch. 5)") \
    X("project", runProject, "PROJECT.smproj", "List the remesh runs of a StrataMesh project (parameters, sizes, validity, review progress) as JSON, without remeshing") \
    /* end of the list */
// clang-format on

namespace stratamesh::cli {

#define STRATAMESH_CLI_DECLARE(name, function, arguments, summary) int function(CommandArgs &args);
STRATAMESH_CLI_COMMANDS(STRATAMESH_CLI_DECLARE)
#undef STRATAMESH_CLI_DECLARE

struct Command {
    const char *name;
    int (*run)(CommandArgs &args);
    const char *arguments;
    const char *summary;
};

// In the order of the list above.
const std::vector<Command> &commands();
// nullptr when there is no such command.
const Command *findCommand(const QString &name);

} // namespace stratamesh::cli
