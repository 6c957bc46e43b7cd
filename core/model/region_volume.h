// Signed region volumes from the region sides (thesis §3.3.1 "size" of a region; Table 3.3),
// with the Gocad side rule of formats.md §0 fact 1: in the z-up frame, a region listed with a
// positive side of surface k lies on the side the right-hand normal of k points to.
// With this rule every real region has a positive volume and the Universe has −(sum).
#pragma once

#include "model/model.h"

#include <vector>

namespace stratamesh {

// det(p0 − ref, p1 − ref, p2 − ref) / 6 of one triangle of the surface.
double triangleConeVolume(const Surface &surface, const Triangle &t, const Vec3 &ref);

// Σ over triangles of det(p0 − ref, p1 − ref, p2 − ref) / 6: the volume of the cone from ref.
// Sums of these over a closed, outward-oriented set of triangles do not depend on ref.
double surfaceConeVolume(const Surface &surface, const Vec3 &ref);

// A reference point for the cone volumes: the centre of the bounding box of all surface vertices
// (keeps the sums well conditioned with coordinates like 1.6e6).
Vec3 volumeReferencePoint(const Model &model);

// Signed volume of a set of sides: positive when they bound a region lying on their sides.
// A surface listed with both signs cancels out (internal surface, e.g. a dangling fault).
double sidesVolume(const Model &model, const std::vector<RegionSide> &sides);

// The volume of each region, in the order of Model::regions.
std::vector<double> regionVolumes(const Model &model);

// The Universe volume: from Model::universe when the file gave its sides, else −(Σ regions).
double universeVolume(const Model &model);

// Volume enclosed by the given surfaces, computed without any region side: their triangles are
// oriented consistently by propagation across shared edges (global vertex ids; requires topology)
// and each closed shell contributes |signed volume|. Throws InputError when an edge of these
// surfaces is not shared by exactly two of their triangles (the shell is not closed).
double enclosedVolume(const Model &model, const std::vector<int> &surfaces);

// enclosedVolume() of the box: the surfaces of type Boundary. Throws InputError when there is none.
double boxEnclosedVolume(const Model &model);

} // namespace stratamesh
