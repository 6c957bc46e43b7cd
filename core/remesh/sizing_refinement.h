// Splits the input triangles that are coarser than a sizing field, so that the field can be
// carried by the domain. The CVT density lives on the domain points and is interpolated linearly
// over each triangle; real models have triangles of hundreds of metres stretched along their
// contacts (modelA5: mean Q 0.43, edges of about 400 m), so a size of 20 m near a contact would
// be smeared over the whole triangle and the sites that should grade the surface away from the
// contact would spread evenly instead, leaving needles between the contact and coarse cells.
// Edges are split at their midpoints, conformally across every surface and line holding them;
// the geometry, the entities and their ids do not change, only vertices are added.
#pragma once

#include "model/model.h"
#include "remesh/feature_sizing.h"

#include <array>
#include <vector>

namespace stratamesh {

struct SizedModel {
    Model model;                             // the input with its edges split
    std::vector<double> size;                // the graded size field per model vertex
    std::vector<std::array<int, 2>> parents; // per vertex added: the ends of the edge it split
    int firstAdded = 0;                      // the vertices from here on were added
};

// Up to `passes` rounds: the size field of `params` is computed on the model, then every edge
// longer than the size at its finer end and whose midpoint lies within `radius` of a target is
// split (an empty `targets` means everywhere). `model` with topology.
SizedModel refineToSize(const Model &model, const FeatureSizingParams &params,
                        const std::vector<Vec3> &targets, double radius, int passes);

// Extends a per-vertex field of `sized`'s input to its added vertices (the mean over the parents).
std::vector<double> extendToAdded(const SizedModel &sized, std::vector<double> field);

} // namespace stratamesh
