// Sites whose restricted cell became empty during the optimisation are put back on the model
// ("no site lost", issue 3): a site without a cell has no gradient and would never return.
// The boundary energy (thesis §4.3.2) causes this: it hands line pieces to the sites closest to
// the line, and can squeeze out a small cell near a contact. Not in the thesis: our addition.
#pragma once

#include "voronoi/cell_integrals.h"
#include "voronoi/restriction_domain.h"

#include <vector>

namespace stratamesh {

// Moves each site with an empty cell (in index order) to the midpoint between the site of a
// donor cell and the donor cell's point farthest from it, donors taken by decreasing mass. That
// point is then strictly closer to the moved site than to any other, so its cell is not empty.
// pointOwners are the owners of the domain points for these sites. Returns how many moved.
int relocateLostSites(const RestrictionDomain &domain, const CellIntegrals &cells,
                      const std::vector<int> &pointOwners, std::vector<Vec3> &sites);

} // namespace stratamesh
