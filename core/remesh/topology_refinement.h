// Local refinement where a remesh broke validity or the input's topology (thesis §4.6.2: where a
// restricted Voronoi cell is not a topological ball, "the number of sites should be increased
// locally"; Edelsbrunner & Shah 1997, Yan, Wang, Lévy & Liu 2009 refine exactly there). The
// remesher's own records say where: a cell holding two corners (corner_merge), a component with
// more than two points (multi_point_merge), lines and corners lost or created, surface parts
// lost or created, unresolved intersections; the validity report adds every other problem.
// Around those places the CVT density is raised and sites are added, then the sites are
// re-optimised and the mesh rebuilt, until nothing is left or the round cap is reached.
#pragma once

#include "model/validity.h"
#include "remesh/simplification_ledger.h"
#include "voronoi/restriction_domain.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stratamesh {

// True for the records that change the topology (surfaces, lines and corners lost or created).
bool isTopologyEdit(LedgerKind kind);

// Names of the input entities involved in the topology edits of `ledger`, each once, in the
// order of the records (what a run that could not keep the topology tells its user).
std::vector<std::string> topologyEditEntities(const SimplificationLedger &ledger);

// Points of the input around which the output is wrong: the records of `ledger` from
// `firstRecord` on whose change is not a requested simplification (a change is requested when
// dResolution > 0 and its size is below dResolution), sampled every `spacing` along lost and
// created lines, and the positions of the validity problems. `input` is the model remeshed
// (with topology), `output` the remesh (with topology).
std::vector<Vec3> refinementTargets(const Model &input, const Model &output,
                                    const SimplificationLedger &ledger, std::size_t firstRecord,
                                    const ValidityReport &validity, double dResolution,
                                    double spacing);

// Multiplies the density of the domain points within `radius` of a target by `factor` (an empty
// density stands for 1 everywhere).
void raiseDensity(const RestrictionDomain &domain, const std::vector<Vec3> &targets, double radius,
                  double factor, std::vector<double> &density);

// `count` points on the domain triangles whose centroid lies within `radius` of a target,
// uniformly by area (deterministic for a seed); empty when no triangle is that close.
std::vector<Vec3> sampleNearTargets(const RestrictionDomain &domain,
                                    const std::vector<Vec3> &targets, double radius, int count,
                                    std::uint64_t seed);

// Sites that pin the features near the targets (Cheng, Dey & Ramos 2007 protect the features of a
// piecewise smooth complex the same way, before the surfaces): one on every corner of `model`
// within `radius` of a target, and along every line, within that radius, one every size[v] of
// length, where `size` (per model vertex) is the graded local feature size. A cell around a site
// on a corner holds no other corner, and line sites as close as the nearest other feature keep
// each line in cells of its own, whatever the site spacing elsewhere. Only where size < coarse.
std::vector<Vec3> featureSitesNearTargets(const Model &model, const std::vector<double> &size,
                                          const std::vector<Vec3> &targets, double radius,
                                          double coarse);

// Free sites that grade the surfaces around the pinned features: on the domain triangles within
// `radius` of a target whose size (mean of `size` at its corners, per domain point) is below
// `coarse`, as many as the size field asks beyond a uniform `coarse` spacing, (coarse/h)² − 1
// per hexagonal cell of side `coarse`, placed with that weight (deterministic for a seed). The
// density of those points is raised to (coarse/h)⁴ so that the CVT keeps them graded.
std::vector<Vec3> gradedSitesNearTargets(const RestrictionDomain &domain,
                                         const std::vector<double> &size,
                                         const std::vector<Vec3> &targets, double radius,
                                         double coarse, std::uint64_t seed,
                                         std::vector<double> &density);

// Number of `sites` within `radius` of a target.
int sitesNearTargets(const std::vector<Vec3> &sites, const std::vector<Vec3> &targets,
                     double radius);

} // namespace stratamesh
