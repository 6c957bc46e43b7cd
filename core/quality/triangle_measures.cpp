#include "quality/triangle_measures.h"

#include "common/error.h"
#include "quality/hausdorff.h"
#include "quality/triangle_quality.h"

#include <algorithm>

namespace stratamesh {

namespace {

// Calls visit(surface, triangle, value, centroid) for every triangle, checking its indices.
template <typename Visit>
void forEachMeasure(const Model &model, TriangleMeasure measure, Visit visit)
{
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const Surface &surface = model.surfaces[s];
        const int n = static_cast<int>(surface.vertices.size());
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            const Triangle &tri = surface.triangles[t];
            for (int v : tri)
                if (v < 0 || v >= n)
                    throw InputError("surface '" + surface.name + "': triangle " + std::to_string(t)
                                     + " refers to vertex " + std::to_string(v) + " of "
                                     + std::to_string(n));
            const Vec3 &a = surface.vertices[tri[0]];
            const Vec3 &b = surface.vertices[tri[1]];
            const Vec3 &c = surface.vertices[tri[2]];
            const TriangleShape shape = triangleShape(a, b, c);
            const double value =
                measure == TriangleMeasure::Quality ? shape.quality : shape.minAngleDeg;
            visit(int(s), int(t), value, Vec3((a + b + c) / 3.0));
        }
    }
}

} // namespace

std::vector<std::vector<double>> triangleMeasures(const Model &model, TriangleMeasure measure)
{
    std::vector<std::vector<double>> values(model.surfaces.size());
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        values[s].reserve(model.surfaces[s].triangles.size());
    forEachMeasure(model, measure, [&](int s, int, double value, const Vec3 &) {
        values[std::size_t(s)].push_back(value);
    });
    return values;
}

std::vector<MeasuredTriangle> trianglesInBin(const Model &model, TriangleMeasure measure,
                                             const Histogram &bins, int bin)
{
    std::vector<MeasuredTriangle> selected;
    if (bin < 0 || std::size_t(bin) >= bins.binCount())
        return selected;
    forEachMeasure(model, measure, [&](int s, int t, double value, const Vec3 &centroid) {
        if (bins.binOf(value) == bin)
            selected.push_back({s, t, value, centroid});
    });
    return selected;
}

std::vector<MeasuredTriangle> trianglesByMeasure(const Model &model, TriangleMeasure measure)
{
    std::vector<MeasuredTriangle> all;
    all.reserve(model.triangleCount());
    forEachMeasure(model, measure, [&](int s, int t, double value, const Vec3 &centroid) {
        all.push_back({s, t, value, centroid});
    });
    std::stable_sort(
        all.begin(), all.end(),
        [](const MeasuredTriangle &a, const MeasuredTriangle &b) { return a.value < b.value; });
    return all;
}

std::vector<std::vector<double>> vertexDistances(const Model &from, const Model &to)
{
    std::vector<Vec3> points;
    for (const Surface &surface : from.surfaces)
        points.insert(points.end(), surface.vertices.begin(), surface.vertices.end());
    if (to.triangleCount() == 0)
        throw InputError("distance to a model without triangles");
    const std::vector<double> all = distancesToModel(to, points);
    std::vector<std::vector<double>> distances(from.surfaces.size());
    std::size_t k = 0;
    for (std::size_t s = 0; s < from.surfaces.size(); ++s) {
        const std::size_t n = from.surfaces[s].vertices.size();
        distances[s].assign(all.begin() + std::ptrdiff_t(k), all.begin() + std::ptrdiff_t(k + n));
        k += n;
    }
    return distances;
}

} // namespace stratamesh
