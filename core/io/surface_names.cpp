#include "io/surface_names.h"

#include <unordered_set>

namespace stratamesh {

std::string patchName(const std::string &object, std::size_t patchCount, std::size_t k)
{
    return patchCount == 1 ? object : object + "_" + std::to_string(k + 1);
}

void makeSurfaceNamesUnique(Model &model)
{
    std::unordered_set<std::string> used;
    for (Surface &s : model.surfaces) {
        if (used.insert(s.name).second)
            continue;
        for (int j = 2;; ++j) {
            std::string candidate = s.name + "_" + std::to_string(j);
            if (used.insert(candidate).second) {
                s.name = std::move(candidate);
                break;
            }
        }
    }
}

} // namespace stratamesh
