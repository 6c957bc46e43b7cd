#include "volume/tetgen_comparison.h"

#include "common/progress.h"
#include "model/region_volume.h"

namespace stratamesh {

TetmeshSide tetmeshModel(const Model &model, const TetgenParams &params, Progress &progress)
{
    TetmeshSide side;
    side.brepVolumes = regionVolumes(model);
    Progress meshing = progressRange(progress, 0.0, 0.9);
    side.result = runTetgen(model, params, meshing);
    side.regions.resize(model.regions.size());
    if (side.result.outcome != TetgenOutcome::Ok)
        return side;
    VolumeMesh &mesh = side.result.mesh;
    Progress measuring = progressRange(progress, 0.9, 1.0);
    side.quality = volumeQuality(mesh, measuring);
    side.regions = regionTets(mesh);
    mesh.cellQuality.clear();
    for (const TetQuality &q : tetQualities(mesh))
        mesh.cellQuality.push_back(q.minDihedralDeg);
    mesh.qualityName = "min_dihedral_deg";
    return side;
}

TetmeshComparison compareTetmeshes(const Model &input, const Model &output,
                                   const TetgenParams &params, Progress &progress)
{
    TetmeshComparison c;
    Progress first(progress, 0.0, 0.5, "input");
    c.input = tetmeshModel(input, params, first);
    Progress second(progress, 0.5, 1.0, "remesh");
    c.output = tetmeshModel(output, params, second);
    progress.tick(1.0, "TetGen comparison done");
    return c;
}

} // namespace stratamesh
