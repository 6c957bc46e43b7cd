#include "remesh/mesh_smoothing.h"

#include "quality/triangle_quality.h"

#include <algorithm>
#include <limits>

namespace stratamesh {

namespace {

double worstQualityAround(const EditableSoup &soup, int v, const Vec3 &at)
{
    double worst = std::numeric_limits<double>::max();
    for (int t : soup.vertexTriangles(v)) {
        const auto &tv = soup.triangle(t).v;
        std::array<Vec3, 3> p;
        for (int k = 0; k < 3; ++k)
            p[k] = tv[k] == v ? at : soup.position(tv[k]);
        worst = std::min(worst, triangleQuality(p[0], p[1], p[2]));
    }
    return worst;
}

} // namespace

int relaxVertices(EditableSoup &soup, InputProjector &projector, const SmoothingParams &params)
{
    int moves = 0;
    for (int pass = 0; pass < params.passes; ++pass) {
        int passMoves = 0;
        for (int v = 0; v < soup.pointCount(); ++v) {
            if (soup.vertexTriangles(v).empty())
                continue;
            const VertexClass c = soup.vertexClass(v);
            Vec3 target;
            if (c == VertexClass::Interior) {
                Vec3 sum = Vec3::Zero();
                const std::vector<int> ring = soup.neighbours(v);
                for (int w : ring)
                    sum += soup.position(w);
                const int surface = soup.triangle(soup.vertexTriangles(v).front()).surface;
                target = projector.onSurface(surface, sum / static_cast<double>(ring.size()));
            } else if (c == VertexClass::Line && params.lines && !soup.point(v).lines.empty()) {
                Vec3 sum = Vec3::Zero();
                int count = 0;
                for (int w : soup.neighbours(v))
                    if (soup.isFeatureEdge(v, w)) {
                        sum += soup.position(w);
                        ++count;
                    }
                if (count != 2)
                    continue;
                target = projector.onLines(soup.point(v).lines, sum / 2.0);
            } else {
                continue;
            }
            const Vec3 old = soup.position(v);
            const double before = worstQualityAround(soup, v, old);
            for (double f : {1.0, 0.5}) {
                const Vec3 candidate = old + f * (target - old);
                if (worstQualityAround(soup, v, candidate) < before)
                    continue;
                if (soup.tryMove(v, candidate, 0.0)) {
                    ++passMoves;
                    break;
                }
            }
        }
        moves += passMoves;
        if (passMoves == 0)
            break;
    }
    return moves;
}

} // namespace stratamesh
