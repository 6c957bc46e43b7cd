#include "complexity/element_sizes.h"

#include "model/region_volume.h"

#include <Eigen/Geometry>

namespace stratamesh {

double surfaceArea(const Surface &surface)
{
    double area = 0.0;
    for (const Triangle &t : surface.triangles) {
        const Vec3 &a = surface.vertices[t[0]];
        area += 0.5 * (surface.vertices[t[1]] - a).cross(surface.vertices[t[2]] - a).norm();
    }
    return area;
}

double lineLength(const Model &model, const Line &line)
{
    const std::size_t n = line.vertices.size();
    double length = 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k)
        length += (model.vertices[line.vertices[k + 1]] - model.vertices[line.vertices[k]]).norm();
    if (line.closed && n > 2)
        length +=
            (model.vertices[line.vertices.front()] - model.vertices[line.vertices.back()]).norm();
    return length;
}

ElementSizes elementSizes(const Model &model)
{
    ElementSizes sizes;
    sizes.regions = regionVolumes(model);
    for (const Surface &s : model.surfaces)
        sizes.surfaces.push_back(surfaceArea(s));
    for (const Line &l : model.lines)
        sizes.lines.push_back(lineLength(model, l));
    return sizes;
}

} // namespace stratamesh
