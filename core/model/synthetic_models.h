// Structural models built in code: test fixtures for every algorithm and the GUI's bundled sample.
// They mimic the thesis's synthetic suite (§3.4, Fig 3.4: a folded layer cake in a box, cut by a
// regional normal fault; the thin layer of model A5's Allan diagram) at a chosen resolution.
// Every surface is conformal along its contacts (shared vertices computed by one function, so
// they are bit-identical), regions and Universe sides follow formats.md §0, coordinates are z-up.
#pragma once

#include "model/model.h"

namespace stratamesh {

// A box [0, size.x] × [0, size.y] × [0, size.z] cut by horizons and optionally one planar fault.
// Horizons are z = c + fold(y), fold(y) = foldAmplitude · sin(π y / size.y) (a cylindrical
// anticline whose axis runs along x). The fault strikes along y and dips towards +x; its hanging
// wall (the +x block) is lowered by faultThrow (a normal fault).
struct LayeredBoxParams {
    Vec3 size{1000.0, 600.0, 400.0};
    int horizons = 2;           // evenly spaced in the room left by the fold and the throw
    double foldAmplitude = 0.0; // ≥ 0
    bool fault = false;
    double faultDipDegrees = 90.0;   // (0, 90]; 90 is vertical
    double faultPosition = 0.5;      // where the fault crosses mid-height, as a fraction of size.x
    double faultThrow = 0.0;         // ≥ 0, vertical offset of the +x block
    double thinLayerThickness = 0.0; // > 0 adds a horizon this far above the lowest one
    double edgeLength = 100.0;       // target triangle edge length
    // A fault network: when not empty, these parallel faults (same dip, towards +x) replace the
    // single fault above. Positions are where each crosses mid-height (fractions of size.x,
    // increasing); each lowers everything east of it by its throw. Faults F1..Fn, fault blocks
    // "_b0".."_bn" from the west.
    std::vector<double> faultPositions;
    std::vector<double> faultThrows;
};

// Surfaces: the box split into patches by the contacts (type Boundary, feature "box"), horizon
// patches (features "H1", "H2", ... from the bottom; the thin layer's top is a horizon too) and
// fault patches (feature "F1"). Regions: one per layer and fault block, grouped in layers.
// Throws InputError when the parameters leave no room (a horizon would leave the box, the fault
// would leave it, non-positive sizes or edge length).
Model layeredBox(const LayeredBoxParams &params);

// A training model like the industrial ones: `faults` (1..10) parallel low-dip normal faults
// (dip in degrees) across a folded box 400 high with `horizons` horizons, throws cycling through
// 0.3, 1.5, 0.6, 2.5 × throwUnit (choose throwUnit near the remesh edge length, so that some fault
// strips are narrower than it and some wider); horizons are cut into faults + 1 pieces. The input
// mesh has edges of about edgeLength.
Model faultNetworkBox(int faults, double dipDegrees, int horizons, double throwUnit,
                      double edgeLength);

struct NestedSpheresParams {
    Vec3 centre = Vec3::Zero();
    double innerRadius = 1.0;
    double outerRadius = 2.0;
    // > 0: a third sphere "middle" between them (thesis Fig 5.9, three nested spheres), whose
    // shells "shell" (inner-middle) and "shell2" (middle-outer) can be made thin.
    double middleRadius = 0.0;
    int subdivisions = 3;    // icosahedron subdivisions: 20 · 4^n triangles per sphere
    bool withRegions = true; // "inner" and "shell" regions plus the Universe sides
};

// Two (three) concentric icospheres, normals outward: "inner" (and "middle", type Horizon) and
// "outer" (type Boundary).
// They share no vertex, so the model has no line and no corner.
Model nestedSpheres(const NestedSpheresParams &params);

// The bundled sample: a folded three-horizon box cut by a 60° normal fault (a few thousand
// triangles), valid, used by the GUI when no file is open.
Model sampleModel();

} // namespace stratamesh
