#include "remesh/thin_strips.h"

#include "complexity/element_sizes.h"
#include "model/model_counts.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stratamesh {

namespace {

std::vector<Vec3> polyline(const Model &model, const Line &line)
{
    std::vector<Vec3> points;
    points.reserve(line.vertices.size());
    for (int v : line.vertices)
        points.push_back(model.vertices[v]);
    return points;
}

double distanceToPolyline(const Vec3 &x, const std::vector<Vec3> &points)
{
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 1; i < points.size(); ++i) {
        const Vec3 d = points[i] - points[i - 1];
        const double dd = d.squaredNorm();
        const double t = dd > 0 ? std::clamp((x - points[i - 1]).dot(d) / dd, 0.0, 1.0) : 0.0;
        best = std::min(best, (points[i - 1] + t * d - x).squaredNorm());
    }
    return points.size() == 1 ? (points[0] - x).norm() : std::sqrt(best);
}

// Largest distance from the points to the polyline, or +inf as soon as one is beyond `limit`.
double farthestWithin(const std::vector<Vec3> &from, const std::vector<Vec3> &to, double limit)
{
    double worst = 0.0;
    for (const Vec3 &x : from) {
        const double d = distanceToPolyline(x, to);
        if (d > limit)
            return std::numeric_limits<double>::infinity();
        worst = std::max(worst, d);
    }
    return worst;
}

} // namespace

std::vector<std::pair<double, int>> boundaryLinesByLength(const Model &model, int surface)
{
    std::vector<std::pair<double, int>> byLength;
    for (int l : model.surfaces[surface].lines)
        byLength.emplace_back(lineLength(model, model.lines[l]), l);
    std::sort(byLength.rbegin(), byLength.rend());
    return byLength;
}

std::vector<ThinStrip> findThinStrips(const Model &model, double maxWidth)
{
    std::vector<ThinStrip> strips;
    if (!(maxWidth > 0.0) || !model.hasTopology())
        return strips;
    for (int s = 0; s < static_cast<int>(model.surfaces.size()); ++s) {
        const Surface &surface = model.surfaces[s];
        if (isBoxSurface(surface) || surface.lines.size() < 2)
            continue;
        if (std::any_of(surface.lines.begin(), surface.lines.end(),
                        [&](int l) { return model.lines[l].closed; }))
            continue;
        const std::vector<std::pair<double, int>> byLength = boundaryLinesByLength(model, s);
        const double shorterLong = byLength[1].first;
        if (shorterLong <= 4.0 * maxWidth)
            continue;
        bool endsShort = true;
        for (std::size_t k = 2; k < byLength.size(); ++k)
            endsShort =
                endsShort && byLength[k].first <= std::min(2.0 * maxWidth, 0.25 * shorterLong);
        if (!endsShort)
            continue;
        const std::vector<Vec3> a = polyline(model, model.lines[byLength[0].second]);
        const std::vector<Vec3> b = polyline(model, model.lines[byLength[1].second]);
        double width = std::max(farthestWithin(a, b, maxWidth), farthestWithin(b, a, maxWidth));
        // A bulge between the lines is wider than the lines are apart: every vertex counts.
        for (std::size_t v = 0; v < surface.vertices.size() && width <= maxWidth; ++v)
            width = std::max({width, distanceToPolyline(surface.vertices[v], a),
                              distanceToPolyline(surface.vertices[v], b)});
        if (!(width <= maxWidth))
            continue;
        ThinStrip strip;
        strip.surface = s;
        strip.lines = {std::min(byLength[0].second, byLength[1].second),
                       std::max(byLength[0].second, byLength[1].second)};
        strip.width = width;
        strip.length = shorterLong;
        strips.push_back(strip);
    }
    return strips;
}

} // namespace stratamesh
