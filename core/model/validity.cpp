#include "model/validity.h"

#include "model/topology.h"
#include "model/validity_checks.h"

#include <cstdio>
#include <optional>

namespace stratamesh {

namespace validity_detail {

std::string pointText(const Vec3 &p)
{
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.10g, %.10g, %.10g)", p.x(), p.y(), p.z());
    return buffer;
}

Vec3 edgeMidpoint(const Model &model, long long key)
{
    return 0.5 * (model.vertices[edgeKeyFirst(key)] + model.vertices[edgeKeySecond(key)]);
}

} // namespace validity_detail

namespace {

ValidityReport runChecks(const Model &model, bool intersections, Progress &progress)
{
    using namespace validity_detail;
    std::optional<Model> withTopology;
    if (!model.hasTopology())
        withTopology = recoverTopology(model);
    const Model &m = withTopology ? *withTopology : model;

    progress.tick(0.0, "validity: edges");
    CheckInput in{m, surfaceEdges(m)};
    ProblemSink sink;
    checkSurfaceMeshes(in, sink);
    checkCloseVertices(in, sink);
    progress.tick(0.1, "validity: sealing");
    checkSealed(in, sink);
    progress.tick(0.15, "validity: region boundaries");
    checkRegionBoundaries(in, sink);
    if (sink.count(validity_check::regionBoundary) == 0)
        checkRegionShells(in, sink);
    progress.tick(0.2, "validity: intersections");
    if (intersections)
        checkIntersections(in, sink, progress);
    progress.tick(1.0, "validity: done");
    return sink.take();
}

} // namespace

ValidityReport checkValidity(const Model &model, Progress &progress)
{
    return runChecks(model, true, progress);
}

ValidityReport checkValidityExceptIntersections(const Model &model, Progress &progress)
{
    return runChecks(model, false, progress);
}

} // namespace stratamesh
