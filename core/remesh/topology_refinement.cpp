#include "remesh/topology_refinement.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

namespace stratamesh {

namespace {

bool nearAny(const Vec3 &p, const std::vector<Vec3> &targets, double radius2)
{
    for (const Vec3 &t : targets)
        if ((p - t).squaredNorm() <= radius2)
            return true;
    return false;
}

// Vertices of a line, one every `spacing` of length (both ends included).
void sampleLine(const Model &model, const Line &line, double spacing, std::vector<Vec3> &out)
{
    if (line.vertices.empty())
        return;
    double run = spacing;
    for (std::size_t i = 0; i < line.vertices.size(); ++i) {
        const Vec3 &p = model.vertices[line.vertices[i]];
        if (i > 0)
            run += (p - model.vertices[line.vertices[i - 1]]).norm();
        if (run >= spacing || i + 1 == line.vertices.size()) {
            out.push_back(p);
            run = 0.0;
        }
    }
}

// A change the user asked for: below d_resolution. Sizes are lengths or distances except
// areas, compared through their square root.
bool requested(const LedgerRecord &r, double dResolution)
{
    if (!(dResolution > 0.0))
        return false;
    const double size = r.sizeMeaning == "area" ? std::sqrt(std::max(0.0, r.size)) : r.size;
    return size < dResolution;
}

// `count` points on the `chosen` domain triangles, each picked with the weight its entry adds to
// `cumulative`, uniformly inside it (deterministic for a seed).
std::vector<Vec3> sampleByWeight(const RestrictionDomain &domain, const std::vector<int> &chosen,
                                 const std::vector<double> &cumulative, int count,
                                 std::uint64_t seed)
{
    std::vector<Vec3> points;
    if (chosen.empty() || count <= 0)
        return points;
    const double total = cumulative.back();
    std::mt19937_64 random(seed);
    auto uniform = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
    points.reserve(count);
    for (int i = 0; i < count; ++i) {
        const double pick = uniform() * total;
        const std::size_t k = std::min<std::size_t>(
            std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(),
            chosen.size() - 1);
        const Triangle &tri = domain.triangles[chosen[k]];
        double u = uniform(), w = uniform();
        if (u + w > 1.0) {
            u = 1.0 - u;
            w = 1.0 - w;
        }
        const Vec3 &a = domain.points[tri[0]], &b = domain.points[tri[1]],
                   &c = domain.points[tri[2]];
        points.push_back(a + u * (b - a) + w * (c - a));
    }
    return points;
}

} // namespace

bool isTopologyEdit(LedgerKind kind)
{
    switch (kind) {
    case LedgerKind::SurfaceLost:
    case LedgerKind::LineLost:
    case LedgerKind::CornerLost:
    case LedgerKind::SurfaceCreated:
    case LedgerKind::LineCreated:
    case LedgerKind::CornerCreated:
    case LedgerKind::SurfacePartLost:
    case LedgerKind::SurfacePartCreated:
        return true;
    default:
        return false;
    }
}

std::vector<std::string> topologyEditEntities(const SimplificationLedger &ledger)
{
    std::vector<std::string> names;
    for (const LedgerRecord &r : ledger)
        if (isTopologyEdit(r.kind))
            for (const EntityRef &e : r.inputs)
                if (std::find(names.begin(), names.end(), e.name) == names.end())
                    names.push_back(e.name);
    return names;
}

std::vector<Vec3> refinementTargets(const Model &input, const Model &output,
                                    const SimplificationLedger &ledger, std::size_t firstRecord,
                                    const ValidityReport &validity, double dResolution,
                                    double spacing)
{
    // Merges of features closer than d_resolution explain the edits along them (a cancelled
    // throw joins two lines into one, loses the fault strip's corners...).
    std::vector<Vec3> merges;
    if (dResolution > 0.0)
        for (std::size_t i = firstRecord; i < ledger.size(); ++i)
            if (ledger[i].kind == LedgerKind::CloseFeatureMerge)
                merges.push_back(ledger[i].position);
    const double reach = std::max(dResolution, 2.0 * spacing);
    std::vector<Vec3> targets, places;
    for (std::size_t i = firstRecord; i < ledger.size(); ++i) {
        const LedgerRecord &r = ledger[i];
        const bool wrong = r.kind == LedgerKind::IntersectionUnresolved
                           || ((isTopologyEdit(r.kind) || r.kind == LedgerKind::CornerMerge
                                || r.kind == LedgerKind::MultiPointMerge)
                               && !requested(r, dResolution));
        if (!wrong)
            continue;
        places.assign(1, r.position);
        if (r.kind == LedgerKind::LineLost)
            for (const EntityRef &ref : r.inputs)
                if (ref.kind == EntityKind::Line && ref.id >= 0
                    && ref.id < static_cast<int>(input.lines.size()))
                    sampleLine(input, input.lines[ref.id], spacing, places);
        if (r.kind == LedgerKind::LineCreated)
            for (const EntityRef &ref : r.outputs)
                if (ref.kind == EntityKind::Line && ref.id >= 0
                    && ref.id < static_cast<int>(output.lines.size()))
                    sampleLine(output, output.lines[ref.id], spacing, places);
        const bool explained = r.kind != LedgerKind::IntersectionUnresolved
                               && std::any_of(places.begin(), places.end(), [&](const Vec3 &p) {
                                      return nearAny(p, merges, reach * reach);
                                  });
        if (!explained)
            targets.insert(targets.end(), places.begin(), places.end());
    }
    for (const ValidityProblem &p : validity.problems)
        targets.push_back(p.position);
    return targets;
}

void raiseDensity(const RestrictionDomain &domain, const std::vector<Vec3> &targets, double radius,
                  double factor, std::vector<double> &density)
{
    if (density.empty())
        density.assign(domain.points.size(), 1.0);
    const double r2 = radius * radius;
    for (std::size_t v = 0; v < domain.points.size(); ++v)
        if (nearAny(domain.points[v], targets, r2))
            density[v] *= factor;
}

std::vector<Vec3> sampleNearTargets(const RestrictionDomain &domain,
                                    const std::vector<Vec3> &targets, double radius, int count,
                                    std::uint64_t seed)
{
    std::vector<int> chosen;
    std::vector<double> cumulative;
    double total = 0.0;
    const double r2 = radius * radius;
    for (std::size_t t = 0; t < domain.triangles.size(); ++t) {
        const Triangle &tri = domain.triangles[t];
        const Vec3 &a = domain.points[tri[0]], &b = domain.points[tri[1]],
                   &c = domain.points[tri[2]];
        if (!nearAny((a + b + c) / 3.0, targets, r2))
            continue;
        const double area = 0.5 * (b - a).cross(c - a).norm();
        if (!(area > 0.0))
            continue;
        total += area;
        chosen.push_back(static_cast<int>(t));
        cumulative.push_back(total);
    }
    return sampleByWeight(domain, chosen, cumulative, count, seed);
}

std::vector<Vec3> featureSitesNearTargets(const Model &model, const std::vector<double> &size,
                                          const std::vector<Vec3> &targets, double radius,
                                          double coarse)
{
    std::vector<Vec3> out;
    const double r2 = radius * radius;
    auto sizeAt = [&](int v) {
        return v >= 0 && v < static_cast<int>(size.size()) && size[v] > 0.0 ? size[v] : coarse;
    };
    for (const Corner &c : model.corners)
        if (c.vertex >= 0 && nearAny(model.vertices[c.vertex], targets, r2))
            out.push_back(model.vertices[c.vertex]);
    for (const Line &line : model.lines) {
        const std::size_t n = line.vertices.size();
        if (n < 2)
            continue;
        // Walk the polyline, one site each time the length since the last reaches the size
        // there (interpolated along a segment); the start is a corner or, on a closed line,
        // an arbitrary vertex.
        double run = 0.0;
        const std::size_t segments = line.closed ? n : n - 1;
        for (std::size_t i = 0; i < segments; ++i) {
            const int va = line.vertices[i], vb = line.vertices[(i + 1) % n];
            const Vec3 &a = model.vertices[va], &b = model.vertices[vb];
            const double length = (b - a).norm();
            const double ha = sizeAt(va), hb = sizeAt(vb);
            double t = 0.0; // length walked along this segment
            for (;;) {
                const double h =
                    std::max(1e-9 * coarse, ha + (hb - ha) * (t / std::max(length, 1e-300)));
                const double step = h - run;
                if (t + step > length)
                    break;
                t += step;
                run = 0.0;
                const Vec3 p = a + (b - a) * (t / length);
                if (h < coarse && nearAny(p, targets, r2)
                    && !(line.corners[1] >= 0 && i + 1 == segments && (p - b).norm() < 0.5 * hb))
                    out.push_back(p);
            }
            run += length - t;
        }
    }
    return out;
}

std::vector<Vec3> gradedSitesNearTargets(const RestrictionDomain &domain,
                                         const std::vector<double> &size,
                                         const std::vector<Vec3> &targets, double radius,
                                         double coarse, std::uint64_t seed,
                                         std::vector<double> &density)
{
    if (density.empty())
        density.assign(domain.points.size(), 1.0);
    const double r2 = radius * radius;
    auto sizeAt = [&](int v) {
        return v >= 0 && v < static_cast<int>(size.size()) && size[v] > 0.0
                   ? std::min(size[v], coarse)
                   : coarse;
    };
    for (std::size_t v = 0; v < domain.points.size(); ++v) {
        const double h = sizeAt(static_cast<int>(v));
        if (h < coarse && nearAny(domain.points[v], targets, r2))
            density[v] = std::max(density[v], std::pow(coarse / h, 4.0));
    }
    const double cell = std::sqrt(3.0) / 2.0 * coarse * coarse;
    std::vector<int> chosen;
    std::vector<double> cumulative;
    double total = 0.0;
    for (std::size_t t = 0; t < domain.triangles.size(); ++t) {
        const Triangle &tri = domain.triangles[t];
        const double h = (sizeAt(tri[0]) + sizeAt(tri[1]) + sizeAt(tri[2])) / 3.0;
        if (!(h < coarse))
            continue;
        const Vec3 &a = domain.points[tri[0]], &b = domain.points[tri[1]],
                   &c = domain.points[tri[2]];
        if (!nearAny((a + b + c) / 3.0, targets, r2))
            continue;
        const double w = 0.5 * (b - a).cross(c - a).norm() * ((coarse / h) * (coarse / h) - 1.0);
        if (!(w > 0.0))
            continue;
        total += w;
        chosen.push_back(static_cast<int>(t));
        cumulative.push_back(total);
    }
    return sampleByWeight(domain, chosen, cumulative, static_cast<int>(std::lround(total / cell)),
                          seed);
}

int sitesNearTargets(const std::vector<Vec3> &sites, const std::vector<Vec3> &targets,
                     double radius)
{
    const double r2 = radius * radius;
    return static_cast<int>(std::count_if(sites.begin(), sites.end(),
                                          [&](const Vec3 &s) { return nearAny(s, targets, r2); }));
}

} // namespace stratamesh
