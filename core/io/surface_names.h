// How readers name the surfaces they make, and how the Gocad writer recognises those names to
// group patches back into one object: the same rule on both sides, so one place for it.
#pragma once

#include "model/model.h"

#include <cstddef>
#include <string>

namespace stratamesh {

// Patch k of an object cut into patchCount surfaces: the object's name when it is alone, else
// "<object>_<k+1>" (Gocad TFACEs of one TSurf, RINGMesh surfaces of one interface).
std::string patchName(const std::string &object, std::size_t patchCount, std::size_t k);

// Surface names must be unique in a model: a clash gets "_2", "_3", ... appended, in order.
void makeSurfaceNamesUnique(Model &model);

} // namespace stratamesh
