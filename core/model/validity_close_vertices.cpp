// close_vertices: two distinct points closer than kCloseVertexTolerance × the bounding-box
// diagonal. TetGen 1.5 merges such points before meshing ("Point i is replaced by point j",
// tolerance -T, 1e-8 of the diagonal by default), which turns the triangles around them into
// duplicated or intersecting facets: a model our exact checks accept would still abort TetGen.
#include "common/translate_noop.h"
#include "model/bounding_box.h"
#include "model/validity_checks.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace stratamesh::validity_detail {

namespace {

// Names of the surfaces holding each global vertex.
std::vector<std::vector<int>> surfacesOfVertices(const Model &model)
{
    std::vector<std::vector<int>> of(model.vertices.size());
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        for (int g : model.surfaceVertexToGlobal[s])
            if (of[g].empty() || of[g].back() != static_cast<int>(s))
                of[g].push_back(static_cast<int>(s));
    return of;
}

} // namespace

void checkCloseVertices(const CheckInput &in, ProblemSink &sink)
{
    const Model &model = in.model;
    const double tolerance = kCloseVertexTolerance * boundingBoxDiagonal(model.vertices);
    if (!(tolerance > 0.0))
        return;
    // A sweep along x: with a tolerance this small, the window holds a handful of points.
    std::vector<int> order(model.vertices.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return model.vertices[a].x() < model.vertices[b].x(); });
    std::vector<std::vector<int>> surfacesOf;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Vec3 &p = model.vertices[order[i]];
        for (std::size_t j = i + 1; j < order.size(); ++j) {
            const Vec3 &q = model.vertices[order[j]];
            if (q.x() - p.x() >= tolerance)
                break;
            const double d = (q - p).norm();
            if (d >= tolerance)
                continue;
            if (surfacesOf.empty())
                surfacesOf = surfacesOfVertices(model);
            std::vector<std::string> names;
            for (int v : {order[i], order[j]})
                for (int s : surfacesOf[v]) {
                    const std::string &name = model.surfaces[s].name;
                    if (std::find(names.begin(), names.end(), name) == names.end())
                        names.push_back(name);
                }
            char distance[32];
            std::snprintf(distance, sizeof distance, "%.3g", d);
            sink.add(validity_check::closeVertices, names, p,
                     {QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "two distinct points %1 apart at %2, closer than a volume "
                                        "mesher's merge tolerance (TetGen merges them)"),
                      {distance, pointText(p)}});
        }
    }
}

} // namespace stratamesh::validity_detail
