#include "voronoi/restriction_domain.h"

#include "common/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace stratamesh {
namespace {

std::uint64_t edgeKey(int a, int b)
{
    if (a > b)
        std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32)
           | static_cast<std::uint32_t>(b);
}

} // namespace

double RestrictionDomain::surfaceArea() const
{
    double area = 0;
    for (const Triangle &t : triangles)
        area += 0.5 * (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
    return area;
}

double RestrictionDomain::lineLength() const
{
    double length = 0;
    for (const auto &s : segments)
        length += (points[s[1]] - points[s[0]]).norm();
    return length;
}

RestrictionDomain makeRestrictionDomain(const Model &model, std::vector<double> density)
{
    RestrictionDomain d;
    d.surfaceCount = static_cast<int>(model.surfaces.size());
    std::vector<Triangle> local;
    const bool topology = model.hasTopology();
    std::vector<int> offsets; // first point of each surface without topology
    if (topology) {
        d.points = model.vertices;
    } else {
        for (const Surface &s : model.surfaces) {
            offsets.push_back(static_cast<int>(d.points.size()));
            d.points.insert(d.points.end(), s.vertices.begin(), s.vertices.end());
        }
    }
    for (int si = 0; si < d.surfaceCount; ++si) {
        const Surface &s = model.surfaces[si];
        const int nv = static_cast<int>(s.vertices.size());
        for (int ti = 0; ti < static_cast<int>(s.triangles.size()); ++ti) {
            const Triangle &t = s.triangles[ti];
            Triangle g{};
            for (int c = 0; c < 3; ++c) {
                if (t[c] < 0 || t[c] >= nv)
                    throw InputError("surface '" + s.name + "': triangle " + std::to_string(ti)
                                     + " has a vertex index out of range");
                g[c] = topology ? model.surfaceVertexToGlobal[si][t[c]] : offsets[si] + t[c];
            }
            d.triangles.push_back(g);
            d.triangleSurface.push_back(si);
            d.triangleInSurface.push_back(ti);
            local.push_back(t);
        }
    }
    if (topology) {
        d.lineCount = static_cast<int>(model.lines.size());
        for (int li = 0; li < d.lineCount; ++li) {
            const Line &line = model.lines[li];
            const int nv = static_cast<int>(line.vertices.size());
            const int count = line.closed ? nv : nv - 1;
            for (int k = 0; k < count; ++k) {
                d.segments.push_back({line.vertices[k], line.vertices[(k + 1) % nv]});
                d.segmentLine.push_back(li);
            }
        }
        for (const Corner &c : model.corners)
            d.corners.push_back(c.vertex);
    }
    d.density = std::move(density);
    finalizeDomain(d, local);
    return d;
}

void finalizeDomain(RestrictionDomain &d, const std::vector<Triangle> &localTriangles)
{
    const int np = static_cast<int>(d.points.size());
    const int nt = static_cast<int>(d.triangles.size());
    for (int i = 0; i < np; ++i)
        if (!d.points[i].allFinite())
            throw InputError("domain point " + std::to_string(i) + " has a non-finite coordinate");
    if (static_cast<int>(d.triangleSurface.size()) != nt)
        throw InputError("domain: one surface index per triangle is required");
    if (d.triangleInSurface.empty()) {
        d.triangleInSurface.resize(nt);
        for (int t = 0; t < nt; ++t)
            d.triangleInSurface[t] = t;
    }
    for (int t = 0; t < nt; ++t) {
        for (int c = 0; c < 3; ++c)
            if (d.triangles[t][c] < 0 || d.triangles[t][c] >= np)
                throw InputError("domain triangle " + std::to_string(t)
                                 + " has a vertex out of range");
        if (d.triangleSurface[t] < 0)
            throw InputError("domain triangle " + std::to_string(t) + " has no surface");
        d.surfaceCount = std::max(d.surfaceCount, d.triangleSurface[t] + 1);
    }
    if (d.segmentLine.size() != d.segments.size())
        throw InputError("domain: one line index per segment is required");
    for (std::size_t s = 0; s < d.segments.size(); ++s) {
        for (int c = 0; c < 2; ++c)
            if (d.segments[s][c] < 0 || d.segments[s][c] >= np)
                throw InputError("domain segment " + std::to_string(s)
                                 + " has a vertex out of range");
        if (d.segmentLine[s] < 0)
            throw InputError("domain segment " + std::to_string(s) + " has no line");
        d.lineCount = std::max(d.lineCount, d.segmentLine[s] + 1);
    }
    for (int c : d.corners)
        if (c < 0 || c >= np)
            throw InputError("domain corner " + std::to_string(c) + " is out of range");
    if (!d.density.empty()) {
        if (static_cast<int>(d.density.size()) != np)
            throw InputError("density: " + std::to_string(d.density.size()) + " values for "
                             + std::to_string(np) + " points");
        for (int i = 0; i < np; ++i)
            if (!(d.density[i] > 0) || !std::isfinite(d.density[i]))
                throw InputError("density at point " + std::to_string(i)
                                 + " is not a positive number");
    }

    // Edge ids per surface from the connectivity ids.
    const std::vector<Triangle> &conn = localTriangles.empty() ? d.triangles : localTriangles;
    if (static_cast<int>(conn.size()) != nt)
        throw InputError("domain: one local triangle per triangle is required");
    d.edgeIds.assign(3 * nt, -1);
    std::vector<std::unordered_map<std::uint64_t, int>> perSurface(d.surfaceCount);
    int nextId = 0;
    for (int t = 0; t < nt; ++t) {
        auto &map = perSurface[d.triangleSurface[t]];
        for (int e = 0; e < 3; ++e) {
            const auto [it, inserted] =
                map.emplace(edgeKey(conn[t][e], conn[t][(e + 1) % 3]), nextId);
            if (inserted)
                ++nextId;
            d.edgeIds[3 * t + e] = it->second;
        }
    }

    // Segments grouped by line, keeping their given order.
    d.lineOffsets.assign(d.lineCount + 1, 0);
    for (int l : d.segmentLine)
        ++d.lineOffsets[l + 1];
    for (int l = 0; l < d.lineCount; ++l)
        d.lineOffsets[l + 1] += d.lineOffsets[l];
    d.lineSegments.assign(d.segments.size(), -1);
    {
        std::vector<int> fill(d.lineOffsets.begin(), d.lineOffsets.end() - 1);
        for (std::size_t s = 0; s < d.segments.size(); ++s)
            d.lineSegments[fill[d.segmentLine[s]]++] = static_cast<int>(s);
    }
    d.lineClosed.assign(d.lineCount, 0);
    for (int l = 0; l < d.lineCount; ++l) {
        const int first = d.lineOffsets[l], last = d.lineOffsets[l + 1] - 1;
        if (last < first)
            continue;
        for (int k = first; k < last; ++k)
            if (d.segments[d.lineSegments[k]][1] != d.segments[d.lineSegments[k + 1]][0])
                throw InputError("line " + std::to_string(l)
                                 + ": its segments are not given in line order");
        d.lineClosed[l] =
            d.segments[d.lineSegments[last]][1] == d.segments[d.lineSegments[first]][0];
    }
}

} // namespace stratamesh
