#include "complexity/geometric_complexity.h"

#include "common/error.h"
#include "complexity/angle_measure.h"
#include "complexity/box_elements.h"
#include "complexity/element_sizes.h"
#include "complexity/region_thickness.h"
#include "complexity/shape_measure.h"
#include "complexity/surface_width.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace stratamesh {

GeometricComplexity geometricComplexity(const Model &model, const GeometricParams &params,
                                        Progress &progress)
{
    if (!(params.h > 0.0) || !std::isfinite(params.h))
        throw InputError("geometric complexity: h must be a positive size, got "
                         + std::to_string(params.h));
    if (!(params.alphaDegrees > 0.0 && params.alphaDegrees <= 180.0))
        throw InputError("geometric complexity: alpha must be in (0, 180] degrees, got "
                         + std::to_string(params.alphaDegrees));
    const BoxElements box = boxElements(model);
    const ElementSizes sizes = elementSizes(model);
    const double h = params.h;
    GeometricComplexity result;

    progress.tick(0.0, "geometric complexity: regions");
    const std::vector<double> thin = regionThinShares(model, h, progress);
    const std::vector<double> sharp = regionSharpShares(model, params.alphaDegrees);
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
        ElementMeasures m;
        m.element = static_cast<int>(r);
        m.size = std::abs(sizes.regions[r]) <= h * h * h ? 1.0 : 0.0;
        m.thickness = thin[r];
        m.angle = sharp[r];
        result.regions.push_back(m);
        result.regionsTotal += m.sum();
    }

    progress.tick(0.6, "geometric complexity: surfaces");
    const std::vector<int> surfaces = box.innerSurfaces();
    result.surfaces.resize(surfaces.size());
    tbb::parallel_for(std::size_t(0), surfaces.size(), [&](std::size_t i) {
        const int s = surfaces[i];
        ElementMeasures &m = result.surfaces[i];
        m.element = s;
        m.size = sizes.surfaces[s] <= h * h ? 1.0 : 0.0;
        m.shape = surfaceShapeMeasure(model.surfaces[s]);
        m.thickness = surfaceThinShare(model.surfaces[s], h);
        m.angle = surfaceSharpCornerShare(model, s, params.alphaDegrees);
    });
    for (const ElementMeasures &m : result.surfaces)
        result.surfacesTotal += m.sum();

    progress.tick(0.9, "geometric complexity: lines");
    for (int l : box.innerLines()) {
        ElementMeasures m;
        m.element = l;
        m.size = sizes.lines[l] <= h ? 1.0 : 0.0;
        m.shape = lineShapeMeasure(model, model.lines[l]);
        result.lines.push_back(m);
        result.linesTotal += m.sum();
    }
    progress.tick(1.0, "geometric complexity");
    return result;
}

} // namespace stratamesh
