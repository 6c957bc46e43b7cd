// Internal to checkValidity(): the individual checks and the capped problem list they fill.
#pragma once

#include "model/surface_edges.h"
#include "model/validity.h"

namespace stratamesh::validity_detail {

// Collects problems, listing at most ValidityReport::kMaxListedPerCheck per check.
class ProblemSink {
public:
    void add(const char *check, std::vector<std::string> entities, const Vec3 &position,
             MessageText text)
    {
        std::size_t &n = m_report.counts[check];
        ++n;
        m_report.valid = false;
        if (n <= ValidityReport::kMaxListedPerCheck)
            m_report.problems.push_back(
                {check, std::move(entities), position, text.text(), std::move(text)});
    }
    // True when one more problem of this check would not be listed (callers may skip details).
    bool full(const char *check) const
    {
        return m_report.count(check) >= ValidityReport::kMaxListedPerCheck;
    }
    std::size_t count(const char *check) const { return m_report.count(check); }
    ValidityReport take() { return std::move(m_report); }

private:
    ValidityReport m_report;
};

// Everything the checks share; the model has topology.
struct CheckInput {
    const Model &model;
    std::vector<SurfaceEdge> edges; // surfaceEdges(model)
};

void checkSealed(const CheckInput &in, ProblemSink &sink);
// non_manifold_edge, degenerate_triangle, duplicate_triangle, inconsistent_orientation.
void checkSurfaceMeshes(const CheckInput &in, ProblemSink &sink);
void checkIntersections(const CheckInput &in, ProblemSink &sink, Progress &progress);
void checkRegionBoundaries(const CheckInput &in, ProblemSink &sink);
// Run only when the region boundaries are sound: folded_contact, region_pocket.
void checkRegionShells(const CheckInput &in, ProblemSink &sink);
void checkCloseVertices(const CheckInput &in, ProblemSink &sink);

// Helpers for messages.
std::string pointText(const Vec3 &p);
Vec3 edgeMidpoint(const Model &model, long long key);

} // namespace stratamesh::validity_detail
