#include "complexity/size_variation.h"

#include "complexity/box_elements.h"
#include "complexity/count_statistics.h"
#include "complexity/element_sizes.h"

namespace stratamesh {

namespace {
std::vector<double> pick(const std::vector<double> &all, const std::vector<int> &which)
{
    std::vector<double> out;
    for (int i : which)
        out.push_back(all[i]);
    return out;
}
} // namespace

SizeVariation sizeVariation(const Model &model)
{
    const BoxElements box = boxElements(model);
    const ElementSizes sizes = elementSizes(model);
    SizeVariation v;
    v.regions = variationCoefficient(sizes.regions); // the Universe is not a region
    v.surfaces = variationCoefficient(pick(sizes.surfaces, box.innerSurfaces()));
    v.lines = variationCoefficient(pick(sizes.lines, box.innerLines()));
    v.total = v.regions + v.surfaces + v.lines;
    return v;
}

} // namespace stratamesh
