// The corners and lines a .gm file states (Corner_i / Line_i meshes and the boundary lists of
// mesh_entities.txt) against the ones topology recovery finds on its surfaces (topology.h).
// RINGMesh and StrataMesh define lines alike (maximal chains of edges with one set of incident
// surfaces), so on a valid file they agree; a difference is a file whose stated topology does not
// match its own surfaces.
#pragma once

#include "model/model.h"
#include "model/validity.h"

#include <string>
#include <vector>

namespace stratamesh {

// The check name of these problems in a ValidityReport (beside validity_check::*).
inline constexpr const char *kFileTopologyCheck = "file_topology";

// One problem per difference, its message naming the file's entity ("Line 7 (62 vertices from
// (…) to (…))") and what differs: a file line that is no recovered line (compared by their vertex
// positions), a recovered line missing from the file, other incident surfaces, line ends that are
// not its boundary corners, a recovered corner with no Corner entity. Entities are the surfaces
// involved, the position the line's first vertex or the corner. Empty when they agree.
// `model` must be readRingMeshModel(path) after recoverTopology(); throws FileError like the
// reader for a malformed archive, InputError for a model without topology.
std::vector<ValidityProblem> compareRingMeshTopology(const std::string &path, const Model &model);

// Appends those problems to a report (listed up to its per-check limit, all counted).
void addRingMeshTopologyProblems(const std::string &path, const Model &model,
                                 ValidityReport &report);

} // namespace stratamesh
