// Shape of tetrahedra, to compare what TetGen makes of an input model and of its remesh (thesis
// §5.2 judges comparison meshes by their dihedral angles and slivers). Definitions follow the
// Verdict library (Stimpson, Ernst, Knupp, Pébay, Thompson 2007, "The Verdict geometric quality
// library", SAND2007-1751; the metrics of VTK's vtkMeshQuality), normalised to 1 for the regular
// tet and growing as the shape gets worse, so our figures and VTK's can be compared one to one.
// Slivers: minimum dihedral angle below 5° (Cheng, Dey, Edelsbrunner, Facello, Teng 2000,
// "Sliver exudation").
#pragma once

#include "common/progress.h"
#include "mesh/volume_mesh.h"
#include "quality/histogram.h"

#include <array>
#include <cstddef>
#include <vector>

namespace stratamesh {

struct TetQuality {
    double volume = 0.0;      // signed: positive in the VolumeMesh node order
    double radiusRatio = 0.0; // R / (3 r): circumradius over three inradii; +inf when flat
    double aspectRatio = 0.0; // longest edge / (2√6 · inradius); +inf when flat
    double minDihedralDeg = 0.0;
    double maxDihedralDeg = 0.0;
};

inline constexpr double kSliverDihedralDeg = 5.0;

TetQuality tetQuality(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

// The interior dihedral angles (degrees) at edges ab, ac, ad, bc, bd, cd.
std::array<double, 6> dihedralAnglesDeg(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

// One entry per cell of the mesh (pyramids and prisms get a default TetQuality).
std::vector<TetQuality> tetQualities(const VolumeMesh &mesh);

struct VolumeQualityStatistics {
    std::size_t tets = 0;
    std::size_t points = 0;      // points used by a tet
    std::size_t slivers = 0;     // min dihedral < kSliverDihedralDeg
    std::size_t flat = 0;        // zero volume: left out of the ratio means and maxima
    double minDihedralDeg = 0.0; // over all tets (0 when there is none)
    double maxDihedralDeg = 0.0;
    double meanRadiusRatio = 0.0;
    double maxRadiusRatio = 0.0;
    double meanAspectRatio = 0.0;
    double maxAspectRatio = 0.0;
    double minVolume = 0.0;
    double totalVolume = 0.0;
    // Fixed bins so that two meshes compare bin by bin: min dihedral 0–90° and max dihedral
    // 60–180° by 5° (the first min-dihedral bin holds the slivers), 3r/R = 1 / radiusRatio in
    // [0, 1] by 0.05 (1 for the regular tet, 0 for a flat one).
    Histogram minDihedral = Histogram::uniform(0.0, 90.0, 18);
    Histogram maxDihedral = Histogram::uniform(60.0, 180.0, 24);
    Histogram inverseRadiusRatio = Histogram::uniform(0.0, 1.0, 20);
};

// Over the tets of the mesh (other cells are skipped). Throws Cancelled through progress.
VolumeQualityStatistics volumeQuality(const VolumeMesh &mesh,
                                      Progress &progress = Progress::none());

} // namespace stratamesh
