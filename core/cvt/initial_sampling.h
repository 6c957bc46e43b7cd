// Initial random sites on the model surfaces (thesis Alg. 4.1 step 1; Lévy & Bonneel 2013):
// each site falls in a triangle chosen with probability ∝ area × mean density, uniformly inside
// it. The generator is a fixed algorithm (mt19937_64 and 53-bit mantissas), so one seed gives
// the same sites on every platform and for any number of threads.
#pragma once

#include "voronoi/restriction_domain.h"

#include <cstdint>
#include <vector>

namespace stratamesh {

// Throws InputError when count < 1 or the surfaces have no area.
std::vector<Vec3> sampleSurfaces(const RestrictionDomain &domain, int count, std::uint64_t seed);

} // namespace stratamesh
