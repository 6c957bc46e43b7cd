#include "io/gocad_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/atomic_file.h"
#include "io/gocad_writer_common.h"
#include "io/surface_names.h"

#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace stratamesh {

namespace {

struct TSurfGroup {
    std::string name;
    std::vector<int> surfaces;
};

// The word written as a Gocad type; Unknown must not read back as a horizon ("none" would).
std::string typeWord(FeatureType type)
{
    return type == FeatureType::Unknown ? "no_geological_feature" : gocadTypeName(type);
}

std::vector<TSurfGroup> groupSurfaces(const Model &model, const std::vector<int> &selection)
{
    std::map<std::string, std::vector<int>> byObject;
    for (int s : selection)
        if (!model.surfaces[s].sourceObject.empty())
            byObject[model.surfaces[s].sourceObject].push_back(s);
    auto keepsNames = [&](const std::string &object, const std::vector<int> &members) {
        const Surface &first = model.surfaces[members.front()];
        for (std::size_t k = 0; k < members.size(); ++k) {
            const Surface &s = model.surfaces[members[k]];
            if (s.name != patchName(object, members.size(), k) || s.featureName != first.featureName
                || s.type != first.type)
                return false;
        }
        return true;
    };
    std::vector<TSurfGroup> groups;
    std::set<std::string> usedNames;
    std::unordered_set<int> placed;
    for (int s : selection) {
        if (placed.count(s))
            continue;
        const Surface &surface = model.surfaces[s];
        TSurfGroup g;
        auto it = byObject.find(surface.sourceObject);
        if (it != byObject.end() && keepsNames(it->first, it->second)) {
            g.name = it->first;
            g.surfaces = it->second;
        } else {
            g.name = surface.name.empty() ? "surface_" + std::to_string(s + 1) : surface.name;
            g.surfaces = {s};
        }
        const std::string base = g.name;
        for (int j = 2; !usedNames.insert(g.name).second; ++j)
            g.name = base + "_" + std::to_string(j);
        placed.insert(g.surfaces.begin(), g.surfaces.end());
        groups.push_back(std::move(g));
    }
    return groups;
}

// BSTONE/BORDER records of one face: for each line of the surface, the face edge (a, b) running
// from the line's first vertex to its second (both sides of a cut line when both exist).
struct FaceBorder {
    int stone = 0; // local vertex
    int next = 0;  // local vertex
};

std::vector<FaceBorder> faceBorders(const Model &model, int s)
{
    std::vector<FaceBorder> out;
    const Surface &surface = model.surfaces[s];
    if (!model.hasTopology() || static_cast<std::size_t>(s) >= model.surfaceVertexToGlobal.size())
        return out;
    const std::vector<int> &toGlobal = model.surfaceVertexToGlobal[s];
    std::unordered_multimap<int, int> locals;
    for (std::size_t v = 0; v < toGlobal.size(); ++v)
        locals.emplace(toGlobal[v], static_cast<int>(v));
    std::set<std::pair<int, int>> edges;
    for (const Triangle &t : surface.triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    for (int l : surface.lines) {
        if (l < 0 || static_cast<std::size_t>(l) >= model.lines.size())
            continue;
        const Line &line = model.lines[l];
        if (line.vertices.size() < 2)
            continue;
        auto [a0, a1] = locals.equal_range(line.vertices[0]);
        for (auto a = a0; a != a1; ++a) {
            auto [b0, b1] = locals.equal_range(line.vertices[1]);
            for (auto b = b0; b != b1; ++b)
                if (edges.count({std::min(a->second, b->second), std::max(a->second, b->second)}))
                    out.push_back({a->second, b->second});
        }
    }
    return out;
}

void writeTSurfObject(std::ostream &out, const Model &model, const TSurfGroup &group)
{
    const Surface &first = model.surfaces[group.surfaces.front()];
    out << "GOCAD TSurf 1\n";
    writeGocadHeader(out, group.name);
    writeGocadCoordinateSystem(out, model.zPositiveDepth);
    if (!first.featureName.empty())
        out << "GEOLOGICAL_FEATURE " << gocadToken(first.featureName) << '\n';
    out << "GEOLOGICAL_TYPE " << typeWord(first.type) << '\n';
    std::set<int> stoneIds;
    int offset = 0;
    std::vector<std::pair<int, int>> borderPairs;
    for (int s : group.surfaces) {
        const Surface &surface = model.surfaces[s];
        out << "TFACE\n";
        for (std::size_t v = 0; v < surface.vertices.size(); ++v) {
            out << "VRTX " << offset + static_cast<int>(v) + 1 << ' ';
            writeGocadPoint(out, surface.vertices[v], model.zPositiveDepth);
            out << '\n';
        }
        for (const Triangle &t : surface.triangles)
            out << "TRGL " << offset + t[0] + 1 << ' ' << offset + t[1] + 1 << ' '
                << offset + t[2] + 1 << '\n';
        for (const FaceBorder &b : faceBorders(model, s))
            borderPairs.push_back({offset + b.stone + 1, offset + b.next + 1});
        offset += static_cast<int>(surface.vertices.size());
    }
    for (const auto &[stone, next] : borderPairs)
        if (stoneIds.insert(stone).second)
            out << "BSTONE " << stone << '\n';
    int id = offset;
    for (const auto &[stone, next] : borderPairs)
        out << "BORDER " << ++id << ' ' << stone << ' ' << next << '\n';
    out << "END\n";
}

void requireWritable(const Model &model, const std::vector<int> &selection)
{
    if (selection.empty())
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "the model '%1' has no surface to write"),
            {model.name}});
    for (int s : selection)
        if (model.surfaces[s].triangles.empty())
            throw InputError(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "surface '%1' has no triangle: Gocad cannot hold it"),
                            {model.surfaces[s].name}});
    for (int s : selection)
        for (const Triangle &t : model.surfaces[s].triangles)
            for (int v : t)
                if (v < 0 || v >= static_cast<int>(model.surfaces[s].vertices.size()))
                    throw InputError(MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "surface '%1' has a triangle using vertex %2 of %3"),
                        {model.surfaces[s].name, std::to_string(v),
                         std::to_string(model.surfaces[s].vertices.size())}});
}

// Signed ids, five per line, closed by 0 (as Gocad writes them).
void writeIdList(std::ostream &out, const std::vector<std::string> &ids)
{
    std::vector<std::string> all = ids;
    all.push_back("0");
    for (std::size_t i = 0; i < all.size(); ++i)
        out << (i % 5 == 0 ? "  " : " ") << all[i]
            << ((i % 5 == 4 || i + 1 == all.size()) ? "\n" : "");
}

std::string signedId(int id, bool positive)
{
    return (positive ? "+" : "-") + std::to_string(id);
}

} // namespace

void writeGocadModel3d(const Model &model, const std::string &path)
{
    std::vector<int> all(model.surfaces.size());
    for (std::size_t s = 0; s < all.size(); ++s)
        all[s] = static_cast<int>(s);
    requireWritable(model, all);
    for (const Region &r : model.regions)
        for (const RegionSide &side : r.boundaries)
            if (side.surface < 0 || side.surface >= static_cast<int>(model.surfaces.size()))
                throw InputError(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "region '%1' is bounded by surface %2 of %3"),
                    {r.name, std::to_string(side.surface), std::to_string(model.surfaces.size())}});
    const std::vector<TSurfGroup> groups = groupSurfaces(model, all);
    std::vector<int> faceId(model.surfaces.size());
    int nextFace = 1;
    for (const TSurfGroup &g : groups)
        for (int s : g.surfaces)
            faceId[s] = nextFace++;
    const int faceCount = nextFace - 1;

    writeTextFileAtomically(path, [&](std::ostream &out) {
        out << "GOCAD Model3d 1\n";
        writeGocadHeader(out, model.name);
        writeGocadCoordinateSystem(out, model.zPositiveDepth);
        for (const TSurfGroup &g : groups)
            out << "TSURF " << gocadToken(g.name) << '\n';
        for (const TSurfGroup &g : groups)
            for (int s : g.surfaces) {
                const Surface &surface = model.surfaces[s];
                out << "TFACE " << faceId[s] << ' ' << typeWord(surface.type) << ' '
                    << gocadToken(g.name) << '\n';
                for (int v : surface.triangles.front()) {
                    out << "  ";
                    writeGocadPoint(out, surface.vertices[v], model.zPositiveDepth);
                    out << '\n';
                }
            }
        // The Universe takes every side no region claims: the outside of the model boundary.
        std::vector<std::array<bool, 2>> claimed(model.surfaces.size(), {false, false});
        for (const Region &r : model.regions)
            for (const RegionSide &side : r.boundaries)
                claimed[side.surface][side.positive ? 1 : 0] = true;
        std::vector<std::pair<int, std::string>> universe;
        for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
            if (!claimed[s][1])
                universe.push_back({faceId[s], signedId(faceId[s], true)});
            if (!claimed[s][0])
                universe.push_back({faceId[s], signedId(faceId[s], false)});
        }
        std::stable_sort(universe.begin(), universe.end(),
                         [](const auto &a, const auto &b) { return a.first < b.first; });
        std::vector<std::string> universeIds;
        for (const auto &u : universe)
            universeIds.push_back(u.second);
        out << "REGION " << faceCount + 1 << " Universe\n";
        writeIdList(out, universeIds);
        for (std::size_t r = 0; r < model.regions.size(); ++r) {
            const Region &region = model.regions[r];
            out << "REGION " << faceCount + 2 + static_cast<int>(r) << ' '
                << gocadToken(region.name) << '\n';
            std::vector<std::string> ids;
            for (const RegionSide &side : region.boundaries)
                ids.push_back(signedId(faceId[side.surface], side.positive));
            writeIdList(out, ids);
        }
        for (const Layer &layer : model.layers) {
            out << "LAYER " << gocadToken(layer.name) << '\n';
            std::vector<std::string> ids;
            for (int r : layer.regions)
                if (r >= 0 && r < static_cast<int>(model.regions.size()))
                    ids.push_back(std::to_string(faceCount + 2 + r));
            writeIdList(out, ids);
        }
        out << "END\n";
        for (const TSurfGroup &g : groups)
            writeTSurfObject(out, model, g);
    });
}

void writeGocadTSurf(const Model &model, const std::string &path, int surface)
{
    std::vector<int> selection;
    if (surface >= 0) {
        if (surface >= static_cast<int>(model.surfaces.size()))
            throw InputError(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "surface %1 does not exist (the model has %2)"),
                            {std::to_string(surface), std::to_string(model.surfaces.size())}});
        selection.push_back(surface);
    } else {
        for (std::size_t s = 0; s < model.surfaces.size(); ++s)
            selection.push_back(static_cast<int>(s));
    }
    requireWritable(model, selection);
    std::vector<TSurfGroup> groups = groupSurfaces(model, selection);
    if (surface >= 0)
        groups = {{model.surfaces[surface].name, {surface}}};
    writeTextFileAtomically(path, [&](std::ostream &out) {
        for (const TSurfGroup &g : groups)
            writeTSurfObject(out, model, g);
    });
}

} // namespace stratamesh
