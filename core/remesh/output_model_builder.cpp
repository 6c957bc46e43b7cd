#include "remesh/output_model_builder.h"

#include "common/translate_noop.h"
#include "complexity/element_sizes.h"
#include "model/topology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>

namespace stratamesh {

namespace {

int findRoot(std::vector<int> &parent, int x)
{
    while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
    return x;
}

double polylineLength(const Model &m, const Line &l)
{
    double len = 0.0;
    for (std::size_t i = 1; i < l.vertices.size(); ++i)
        len += (m.vertices[l.vertices[i]] - m.vertices[l.vertices[i - 1]]).norm();
    if (l.closed && l.vertices.size() > 1)
        len += (m.vertices[l.vertices.front()] - m.vertices[l.vertices.back()]).norm();
    return len;
}

Vec3 polylineCentroid(const Model &m, const Line &l)
{
    Vec3 c = Vec3::Zero();
    for (int v : l.vertices)
        c += m.vertices[v];
    return l.vertices.empty() ? c : Vec3(c / static_cast<double>(l.vertices.size()));
}

// Sorted names of the surfaces around a line: the key that survives renumbering.
std::vector<std::string> surfaceNames(const Model &m, const std::vector<int> &surfaces)
{
    std::vector<std::string> names;
    for (int s : surfaces)
        names.push_back(m.surfaces[s].name);
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::vector<std::string> cornerSurfaceNames(const Model &m, const Corner &c)
{
    std::vector<int> surfaces;
    for (int l : c.lines)
        surfaces.insert(surfaces.end(), m.lines[l].surfaces.begin(), m.lines[l].surfaces.end());
    return surfaceNames(m, surfaces);
}

// Greedy matching of items with equal keys by increasing distance; returns output match of
// each input item (-1 when unmatched).
template <class Key>
std::vector<int>
matchByKeyAndDistance(const std::vector<Key> &inKeys, const std::vector<Vec3> &inPos,
                      const std::vector<Key> &outKeys, const std::vector<Vec3> &outPos)
{
    struct Candidate {
        double d;
        int in, out;
    };
    std::vector<Candidate> candidates;
    std::map<Key, std::vector<int>> outByKey;
    for (std::size_t o = 0; o < outKeys.size(); ++o)
        outByKey[outKeys[o]].push_back(static_cast<int>(o));
    for (std::size_t i = 0; i < inKeys.size(); ++i) {
        auto it = outByKey.find(inKeys[i]);
        if (it == outByKey.end())
            continue;
        for (int o : it->second)
            candidates.push_back({(inPos[i] - outPos[o]).norm(), static_cast<int>(i), o});
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate &a, const Candidate &b) { return a.d < b.d; });
    std::vector<int> match(inKeys.size(), -1);
    std::vector<char> used(outKeys.size(), 0);
    for (const Candidate &c : candidates)
        if (match[c.in] < 0 && !used[c.out]) {
            match[c.in] = c.out;
            used[c.out] = 1;
        }
    return match;
}

LedgerRecord entityRecord(LedgerKind kind, EntityRef ref, bool isInput, const Vec3 &position,
                          double size, const std::string &meaning, const char *note)
{
    LedgerRecord r;
    r.kind = kind;
    (isInput ? r.inputs : r.outputs).push_back(std::move(ref));
    r.position = position;
    r.size = size;
    r.sizeMeaning = meaning;
    setNote(r, {note, {}});
    return r;
}

} // namespace

std::vector<SurfacePart> surfaceParts(const Surface &surface)
{
    std::vector<int> parent(surface.triangles.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::map<std::pair<int, int>, int> firstByEdge;
    for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t)
        for (int k = 0; k < 3; ++k) {
            int a = surface.triangles[t][k], b = surface.triangles[t][(k + 1) % 3];
            if (a > b)
                std::swap(a, b);
            auto [it, inserted] = firstByEdge.emplace(std::make_pair(a, b), t);
            if (!inserted)
                parent[findRoot(parent, t)] = findRoot(parent, it->second);
        }
    std::map<int, SurfacePart> byRoot;
    for (int t = 0; t < static_cast<int>(parent.size()); ++t) {
        const Triangle &tri = surface.triangles[t];
        const Vec3 &a = surface.vertices[tri[0]], &b = surface.vertices[tri[1]],
                   &c = surface.vertices[tri[2]];
        const double area = 0.5 * (b - a).cross(c - a).norm();
        SurfacePart &part = byRoot[findRoot(parent, t)];
        part.area += area;
        part.centroid += area * (a + b + c) / 3.0;
        ++part.triangles;
    }
    std::vector<SurfacePart> parts;
    for (auto &[root, part] : byRoot) {
        if (part.area > 0)
            part.centroid /= part.area;
        parts.push_back(part);
    }
    std::sort(parts.begin(), parts.end(),
              [](const SurfacePart &x, const SurfacePart &y) { return x.area > y.area; });
    return parts;
}

int surfaceComponentCount(const Surface &surface)
{
    return static_cast<int>(surfaceParts(surface).size());
}

void recordEntityChanges(const Model &input, const Model &output, SimplificationLedger &ledger)
{
    std::map<std::string, int> outByName;
    for (std::size_t s = 0; s < output.surfaces.size(); ++s)
        outByName[output.surfaces[s].name] = static_cast<int>(s);
    for (std::size_t s = 0; s < input.surfaces.size(); ++s) {
        const Surface &in = input.surfaces[s];
        auto it = outByName.find(in.name);
        const int inCount = surfaceComponentCount(in);
        const int outCount =
            it == outByName.end() ? 0 : surfaceComponentCount(output.surfaces[it->second]);
        Vec3 centre = Vec3::Zero();
        for (const Vec3 &v : in.vertices)
            centre += v;
        if (!in.vertices.empty())
            centre /= static_cast<double>(in.vertices.size());
        if (outCount == 0)
            ledger.push_back(entityRecord(
                LedgerKind::SurfaceLost, surfaceRef(input, static_cast<int>(s)), true, centre,
                surfaceArea(in), "area",
                QT_TRANSLATE_NOOP("stratamesh::Core", "surface entirely below the resolution")));
        else
            for (int k = outCount; k < inCount; ++k)
                ledger.push_back(
                    entityRecord(LedgerKind::SurfacePartLost,
                                 surfaceRef(input, static_cast<int>(s)), true, centre, 0.0, "area",
                                 QT_TRANSLATE_NOOP("stratamesh::Core",
                                                   "a connected part of the surface disappeared")));
        if (outCount > inCount) {
            // The largest parts continue the input's; each smaller one is a new piece to review.
            const std::vector<SurfacePart> parts = surfaceParts(output.surfaces[it->second]);
            for (int k = inCount; k < outCount; ++k)
                ledger.push_back(entityRecord(
                    LedgerKind::SurfacePartCreated, surfaceRef(output, it->second), false,
                    parts[k].centroid, parts[k].area, "area",
                    QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "the surface was split into more parts: this one is separate")));
        }
    }

    std::vector<std::vector<std::string>> inKeys, outKeys;
    std::vector<Vec3> inPos, outPos;
    for (const Line &l : input.lines) {
        inKeys.push_back(surfaceNames(input, l.surfaces));
        inPos.push_back(polylineCentroid(input, l));
    }
    for (const Line &l : output.lines) {
        outKeys.push_back(surfaceNames(output, l.surfaces));
        outPos.push_back(polylineCentroid(output, l));
    }
    std::vector<int> match = matchByKeyAndDistance(inKeys, inPos, outKeys, outPos);
    std::vector<char> outMatched(output.lines.size(), 0);
    for (std::size_t i = 0; i < input.lines.size(); ++i) {
        if (match[i] >= 0) {
            outMatched[match[i]] = 1;
            continue;
        }
        ledger.push_back(entityRecord(
            LedgerKind::LineLost, lineRef(input, static_cast<int>(i)), true, inPos[i],
            polylineLength(input, input.lines[i]), "length",
            QT_TRANSLATE_NOOP("stratamesh::Core", "contact or border line not in the output")));
    }
    for (std::size_t o = 0; o < output.lines.size(); ++o)
        if (!outMatched[o])
            ledger.push_back(entityRecord(
                LedgerKind::LineCreated, lineRef(output, static_cast<int>(o)), false, outPos[o],
                polylineLength(output, output.lines[o]), "length",
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "line of the output with no counterpart in the input")));

    inKeys.clear();
    outKeys.clear();
    inPos.clear();
    outPos.clear();
    for (const Corner &c : input.corners) {
        inKeys.push_back(cornerSurfaceNames(input, c));
        inPos.push_back(input.vertices[c.vertex]);
    }
    for (const Corner &c : output.corners) {
        outKeys.push_back(cornerSurfaceNames(output, c));
        outPos.push_back(output.vertices[c.vertex]);
    }
    match = matchByKeyAndDistance(inKeys, inPos, outKeys, outPos);
    std::vector<char> cornerMatched(output.corners.size(), 0);
    for (std::size_t i = 0; i < input.corners.size(); ++i) {
        if (match[i] >= 0) {
            cornerMatched[match[i]] = 1;
            continue;
        }
        double nearest = 0.0;
        if (!outPos.empty()) {
            nearest = std::numeric_limits<double>::max();
            for (const Vec3 &p : outPos)
                nearest = std::min(nearest, (p - inPos[i]).norm());
        }
        ledger.push_back(entityRecord(
            LedgerKind::CornerLost, cornerRef(input, static_cast<int>(i)), true, inPos[i], nearest,
            "distance",
            QT_TRANSLATE_NOOP("stratamesh::Core",
                              "corner not in the output (distance to the nearest output corner)")));
    }
    for (std::size_t o = 0; o < output.corners.size(); ++o)
        if (!cornerMatched[o])
            ledger.push_back(entityRecord(
                LedgerKind::CornerCreated, cornerRef(output, static_cast<int>(o)), false, outPos[o],
                0.0, "distance",
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "corner of the output with no counterpart in the input")));
}

Model buildOutputModel(const Model &input, const OutputMesh &mesh, SimplificationLedger &ledger,
                       Progress &progress)
{
    progress.tick(0.0, "surfaces");
    Model out;
    out.name = input.name;
    out.zPositiveDepth = input.zPositiveDepth;
    std::vector<int> surfaceMap(input.surfaces.size(), -1);
    std::vector<std::vector<int>> bySurface(input.surfaces.size());
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
        bySurface[mesh.triangles[t].surface].push_back(t);
    for (std::size_t s = 0; s < input.surfaces.size(); ++s) {
        if (bySurface[s].empty())
            continue;
        const Surface &in = input.surfaces[s];
        Surface o;
        o.name = in.name;
        o.featureName = in.featureName;
        o.type = in.type;
        o.sourceObject = in.sourceObject;
        std::map<int, int> local;
        for (int t : bySurface[s]) {
            Triangle tri;
            for (int k = 0; k < 3; ++k) {
                const int p = mesh.triangles[t].v[k];
                auto [it, inserted] = local.emplace(p, static_cast<int>(o.vertices.size()));
                if (inserted)
                    o.vertices.push_back(mesh.points[p].position);
                tri[k] = it->second;
            }
            o.triangles.push_back(tri);
        }
        surfaceMap[s] = static_cast<int>(out.surfaces.size());
        out.surfaces.push_back(std::move(o));
    }
    auto mapSides = [&](const std::vector<RegionSide> &sides) {
        std::vector<RegionSide> r;
        for (const RegionSide &side : sides)
            if (side.surface >= 0 && side.surface < static_cast<int>(surfaceMap.size())
                && surfaceMap[side.surface] >= 0)
                r.push_back({surfaceMap[side.surface], side.positive});
        return r;
    };
    for (const Region &region : input.regions)
        out.regions.push_back({region.name, mapSides(region.boundaries)});
    out.universe = mapSides(input.universe);
    out.layers = input.layers;
    progress.tick(0.3, "topology");
    out = recoverTopology(std::move(out));
    progress.tick(0.8, "entity changes");
    recordEntityChanges(input, out, ledger);
    return out;
}

} // namespace stratamesh
