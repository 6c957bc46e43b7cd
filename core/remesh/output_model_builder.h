// Turns the output mesh of the remesher into a new model (thesis §4.4.4, §4.5): each output
// surface keeps the name, feature, type and source object of the input surface it remeshes;
// regions keep their sides; lines and corners are recovered from the conformal output surfaces.
// Input and output entities are then matched (lines and corners by their incident surfaces and
// position) so that every entity lost or created is a ledger record (thesis §4.6.1).
#pragma once

#include "common/progress.h"

#include "remesh/output_mesh.h"
#include "remesh/simplification_ledger.h"

namespace stratamesh {

// `input` must have topology. Surfaces left without triangles are dropped from the output and
// from region boundaries. The output has topology.
Model buildOutputModel(const Model &input, const OutputMesh &mesh, SimplificationLedger &ledger,
                       Progress &progress = Progress::none());

// Records surface, line and corner losses and creations between two models with topology whose
// surfaces correspond by name.
void recordEntityChanges(const Model &input, const Model &output, SimplificationLedger &ledger);

// Connected components of a surface through its local edges, largest area first.
struct SurfacePart {
    double area = 0;
    Vec3 centroid = Vec3::Zero();
    int triangles = 0;
};
std::vector<SurfacePart> surfaceParts(const Surface &surface);
int surfaceComponentCount(const Surface &surface);

} // namespace stratamesh
