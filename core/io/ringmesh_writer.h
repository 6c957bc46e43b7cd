// RINGMesh GeoModel (.gm) output, version 2, laid out as RINGMesh's own writer (io_gm.cpp) does:
// mesh_entities.txt ("Dimension 3", "Version 2", name, counts, Corner/Line/Surface lines with
// their boundaries, Region lines with signed surfaces, Universe), geological_entities.txt
// (Interfaces from the surfaces' feature names and types, Contacts grouping lines by the
// interfaces they touch, Layers), then the entity GeoFiles sorted by name.
//
// Corners and lines come from the model's topology (recovered here when missing); a closed line
// gets a corner at its first vertex, as RINGMesh lines always have two. Surfaces keep their local
// vertices and triangles in order, so coordinates and names survive a round trip bit for bit.
// A line a surface lies on both sides of (an internal border) is listed twice among the
// surface's boundaries, as RINGMesh does.
// The Universe is the model's own when it has one, else every surface side no region claims,
// turned over. Names are written with blanks replaced by '_' (fields are blank-separated).
#pragma once

#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <string>

namespace stratamesh {

// Throws InputError for a model without surfaces or with an empty surface, FileError on write.
// Atomic: the archive is built in a temporary file and renamed over `path`.
void writeRingMeshModel(const Model &model, const std::string &path);

// The surface model of the mesh (modelFromMesh) plus one Region_i.geogram per region holding
// cells (tets, prisms, pyramids).
void writeRingMeshVolume(const VolumeMesh &mesh, const std::string &path);

} // namespace stratamesh
