// A surface Model as an exchange mesh and back, so one writer per format serves both.
#pragma once

#include "mesh/volume_mesh.h"
#include "model/model.h"

namespace stratamesh {

// Points: surface vertices merged by exact position *across* surfaces (so the written mesh is
// conformal), but never two vertices of the same surface (cuts along internal lines survive the
// round trip). Triangles keep their surface; regions keep their names and sides; when the model
// has topology, its lines become edges and its corners corner points. No cells.
VolumeMesh meshFromModel(const Model &model);

// The triangles of each surface become a Surface whose local vertices are the points it uses, in
// increasing point order; untagged triangles (surface -1) form a surface named "untagged".
// Regions come from regionBoundaries (names only when absent). Cells and edges are dropped: call
// recoverTopology() for lines and corners.
Model modelFromMesh(const VolumeMesh &mesh);

} // namespace stratamesh
