#include "quality/mesh_statistics.h"

#include "common/error.h"
#include "quality/triangle_quality.h"

#include <algorithm>
#include <limits>

namespace stratamesh {

namespace {

template <typename Visit>
void forEachTriangle(const Surface &surface, Visit visit)
{
    const int n = static_cast<int>(surface.vertices.size());
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
        const Triangle &tri = surface.triangles[t];
        for (int v : tri) {
            if (v < 0 || v >= n)
                throw InputError("surface '" + surface.name + "': triangle " + std::to_string(t)
                                 + " refers to vertex " + std::to_string(v) + " of "
                                 + std::to_string(n));
        }
        visit(triangleShape(surface.vertices[tri[0]], surface.vertices[tri[1]],
                            surface.vertices[tri[2]]));
    }
}

// Accumulates over surfaces; the bounding box uses surface vertices, which are the same points
// as the merged global ones (the merge is by exact position).
class Accumulator {
public:
    void add(const Surface &surface)
    {
        for (const Vec3 &p : surface.vertices) {
            m_low = m_low.cwiseMin(p);
            m_high = m_high.cwiseMax(p);
            m_hasPoint = true;
        }
        forEachTriangle(surface, [this](const TriangleShape &s) {
            ++m_stats.triangles;
            m_minAngle = std::min(m_minAngle, s.minAngleDeg);
            if (s.minAngleDeg < 30.0)
                ++m_below30;
            m_qualitySum += s.quality;
            m_stats.area += s.area;
        });
    }

    MeshStatistics finish(std::size_t vertexCount)
    {
        m_stats.vertices = vertexCount;
        if (m_stats.triangles > 0) {
            const double n = static_cast<double>(m_stats.triangles);
            m_stats.minAngleDeg = m_minAngle;
            m_stats.pctTrianglesAngleBelow30 = 100.0 * static_cast<double>(m_below30) / n;
            m_stats.meanQuality = m_qualitySum / n;
        }
        m_stats.bboxDiagonal = m_hasPoint ? (m_high - m_low).norm() : 0.0;
        return m_stats;
    }

private:
    MeshStatistics m_stats;
    double m_minAngle = std::numeric_limits<double>::infinity();
    std::size_t m_below30 = 0;
    double m_qualitySum = 0.0;
    bool m_hasPoint = false;
    Vec3 m_low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 m_high = Vec3::Constant(-std::numeric_limits<double>::infinity());
};

std::vector<double> uniformEdges(double low, double high, int bins)
{
    return Histogram::uniform(low, high, bins).edges();
}

} // namespace

MeshStatistics computeMeshStatistics(const Model &model)
{
    Accumulator acc;
    std::size_t localVertices = 0;
    for (const Surface &surface : model.surfaces) {
        acc.add(surface);
        localVertices += surface.vertices.size();
    }
    return acc.finish(model.hasTopology() ? model.vertices.size() : localVertices);
}

MeshStatistics computeMeshStatistics(const Surface &surface)
{
    Accumulator acc;
    acc.add(surface);
    return acc.finish(surface.vertices.size());
}

std::vector<double> minAngleBinEdges()
{
    return uniformEdges(0.0, 60.0, 12);
}
std::vector<double> qualityBinEdges()
{
    return uniformEdges(0.0, 1.0, 20);
}

Histogram minAngleHistogram(const Model &model, const std::vector<double> &edges)
{
    Histogram h(edges);
    for (const Surface &surface : model.surfaces)
        forEachTriangle(surface, [&h](const TriangleShape &s) { h.add(s.minAngleDeg); });
    return h;
}

Histogram qualityHistogram(const Model &model, const std::vector<double> &edges)
{
    Histogram h(edges);
    for (const Surface &surface : model.surfaces)
        forEachTriangle(surface, [&h](const TriangleShape &s) { h.add(s.quality); });
    return h;
}

} // namespace stratamesh
