#include "cvt/site_relocation.h"

#include <algorithm>
#include <numeric>

namespace stratamesh {

int relocateLostSites(const RestrictionDomain &domain, const CellIntegrals &cells,
                      const std::vector<int> &pointOwners, std::vector<Vec3> &sites)
{
    const int n = static_cast<int>(sites.size());
    std::vector<int> lost;
    for (int i = 0; i < n; ++i)
        if (!(cells.mass[i] > 0))
            lost.push_back(i);
    if (lost.empty())
        return 0;
    // The farthest domain point of every cell.
    std::vector<int> farthest(n, -1);
    std::vector<double> distance(n, -1.0);
    for (std::size_t p = 0; p < pointOwners.size(); ++p) {
        const int s = pointOwners[p];
        if (s < 0)
            continue;
        const double d = (domain.points[p] - sites[s]).squaredNorm();
        if (d > distance[s]) {
            distance[s] = d;
            farthest[s] = static_cast<int>(p);
        }
    }
    std::vector<int> donors(n);
    std::iota(donors.begin(), donors.end(), 0);
    std::stable_sort(donors.begin(), donors.end(),
                     [&](int a, int b) { return cells.mass[a] > cells.mass[b]; });
    int moved = 0;
    std::size_t next = 0;
    for (int i : lost) {
        while (next < donors.size()
               && (farthest[donors[next]] < 0 || !(distance[donors[next]] > 0)))
            ++next;
        if (next == donors.size())
            break;
        const int d = donors[next++];
        sites[i] = 0.5 * (sites[d] + domain.points[farthest[d]]);
        ++moved;
    }
    return moved;
}

} // namespace stratamesh
