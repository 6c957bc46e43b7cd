// RINGMesh GeoModel (.gm) input: a zip archive of mesh_entities.txt, geological_entities.txt
// (ringmesh_entities.h) and one Geogram GeoFile per entity (Corner_i, Line_i, Surface_i and,
// when the region is meshed, Region_i .geogram; geogram_file.h, geogram_mesh.h).
//
// Surfaces: one per RINGMesh Surface, in file order, with its own vertices and triangles.
// Their feature is the Interface holding them: name → featureName and sourceObject, geological
// feature → type ("top" horizon, "*fault" fault, "unconformity", "boundary" box; versions 0 and
// 1 also give it on the surface line). A surface is named after its entity when it has a name,
// else after its interface ("Back" for a lone child, "Back_1".."Back_4" otherwise), as the Gocad
// reader names TFACEs. Regions keep their names and signed sides, which follow the Gocad rule of
// model.h (RINGMesh converts .ml to z-up and keeps the signs), so volumes come out positive.
// Layers come from the Layer geological entities. Coordinates are used as stored (z-up).
// Corner and Line meshes are read and checked, but lines and corners come from topology recovery.
#pragma once

#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <string>

namespace stratamesh {

// The B-Rep, without topology (call recoverTopology). Throws FileError("archive:entry:line:
// cause", or "archive:entry: cause") for a corrupt archive, a missing entity file, a malformed
// GeoFile, or meshes and counts that disagree with mesh_entities.txt.
Model readRingMeshModel(const std::string &path);

// meshFromModel(readRingMeshModel(path)) plus the cells of every meshed region (Region_i.geogram),
// tagged with the region; cell vertices are merged with the surface points by exact position.
// A model without region meshes gives a mesh without cells.
VolumeMesh readRingMeshVolume(const std::string &path);

// True for the .gm extension (case-insensitive).
bool isRingMeshFile(const std::string &path);
// True when the archive holds at least one Region_i.geogram (reads the zip directory only).
bool hasRingMeshRegionMeshes(const std::string &path);

} // namespace stratamesh
