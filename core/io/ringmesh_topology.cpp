#include "io/ringmesh_topology.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/geogram_mesh.h"
#include "io/ringmesh_archive.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace stratamesh {

namespace {

using PointSet = std::vector<PointKey>; // sorted, unique

PointSet pointSet(const std::vector<Vec3> &points)
{
    PointSet s;
    for (const Vec3 &p : points)
        s.push_back(pointKey(p));
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

std::string text(const Vec3 &p)
{
    std::ostringstream out;
    out.precision(10);
    out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return out.str();
}

std::string describe(const std::string &what, const std::vector<Vec3> &points)
{
    return what + " (" + std::to_string(points.size()) + " vertices from " + text(points.front())
           + " to " + text(points.back()) + ")";
}

std::string list(const std::set<int> &ids)
{
    std::string out = "{";
    for (int i : ids)
        out += (out.size() > 1 ? ", " : "") + std::to_string(i);
    return out + "}";
}

} // namespace

std::vector<ValidityProblem> compareRingMeshTopology(const std::string &path, const Model &model)
{
    if (!model.hasTopology())
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP(
                "stratamesh::Core",
                "compareRingMeshTopology needs the recovered topology (recoverTopology)"),
            {}});
    const GmArchive gm(path);
    const GmMeshEntities &e = gm.entities();
    std::vector<ValidityProblem> problems;
    const auto add = [&](const std::set<int> &surfaces, const Vec3 &position, std::string message) {
        ValidityProblem p;
        p.check = kFileTopologyCheck;
        for (int s : surfaces)
            if (s >= 0 && std::size_t(s) < model.surfaces.size())
                p.entities.push_back(model.surfaces[s].name);
        p.position = position;
        p.message = std::move(message);
        problems.push_back(std::move(p));
    };

    std::vector<Vec3> cornerPoint;
    for (std::size_t c = 0; c < e.of(GmEntityType::Corner).size(); ++c) {
        const std::string where = gm.where(gmEntryName(GmEntityType::Corner, c));
        const std::vector<Vec3> p = geogramPoints(gm.geogram(GmEntityType::Corner, c), where);
        if (p.size() != 1)
            throw FileError(
                where, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "a corner has one vertex, this one has %1"),
                            {std::to_string(p.size())}});
        cornerPoint.push_back(p[0]);
    }

    // Recovered lines by the positions of their vertices.
    std::map<PointSet, int> recovered;
    for (std::size_t l = 0; l < model.lines.size(); ++l) {
        std::vector<Vec3> points;
        for (int v : model.lines[l].vertices)
            points.push_back(model.vertices[v]);
        recovered.emplace(pointSet(points), int(l));
    }
    // File surfaces incident to each file line: the surfaces listing it as boundary.
    std::vector<std::set<int>> fileSurfaces(e.of(GmEntityType::Line).size());
    for (std::size_t s = 0; s < e.of(GmEntityType::Surface).size(); ++s)
        for (int l : e.of(GmEntityType::Surface)[s].boundaries)
            fileSurfaces[l].insert(int(s));

    std::vector<char> matched(model.lines.size(), 0);
    for (std::size_t l = 0; l < e.of(GmEntityType::Line).size(); ++l) {
        const std::string where = gm.where(gmEntryName(GmEntityType::Line, l));
        const std::vector<Vec3> points = geogramPoints(gm.geogram(GmEntityType::Line, l), where);
        if (points.empty())
            throw FileError(where, 0,
                            QT_TRANSLATE_NOOP("stratamesh::Core", "a line without vertices"));
        const std::string name = describe("Line " + std::to_string(l), points);
        const auto it = recovered.find(pointSet(points));
        if (it == recovered.end()) {
            add(fileSurfaces[l], points.front(),
                name + " of the file is not a line of the recovered topology");
            continue;
        }
        matched[it->second] = 1;
        const Line &line = model.lines[it->second];
        const std::set<int> ours(line.surfaces.begin(), line.surfaces.end());
        if (ours != fileSurfaces[l])
            add(ours, points.front(),
                name + ": the file gives it the surfaces " + list(fileSurfaces[l])
                    + ", the recovered topology " + list(ours));
        const std::vector<int> &corners = e.of(GmEntityType::Line)[l].boundaries;
        std::set<PointKey> ends{pointKey(points.front()), pointKey(points.back())};
        std::set<PointKey> stated;
        for (int c : corners)
            stated.insert(pointKey(cornerPoint[c]));
        if (corners.size() != 2 || stated != ends)
            add(ours, points.front(),
                name + ": its boundary corners in mesh_entities.txt are not its two ends");
    }
    for (std::size_t l = 0; l < model.lines.size(); ++l) {
        if (matched[l])
            continue;
        std::vector<Vec3> points;
        for (int v : model.lines[l].vertices)
            points.push_back(model.vertices[v]);
        const std::set<int> surfaces(model.lines[l].surfaces.begin(),
                                     model.lines[l].surfaces.end());
        add(surfaces, points.front(),
            describe("recovered line " + std::to_string(l), points) + " is not in the file");
    }
    std::set<PointKey> fileCorners;
    for (const Vec3 &p : cornerPoint)
        fileCorners.insert(pointKey(p));
    for (std::size_t c = 0; c < model.corners.size(); ++c) {
        const Vec3 &p = model.vertices[model.corners[c].vertex];
        if (!fileCorners.count(pointKey(p)))
            add({}, p,
                "recovered corner " + std::to_string(c) + " at " + text(p)
                    + " is no Corner of the file");
    }
    return problems;
}

void addRingMeshTopologyProblems(const std::string &path, const Model &model,
                                 ValidityReport &report)
{
    for (ValidityProblem &p : compareRingMeshTopology(path, model)) {
        if (report.counts[p.check]++ < ValidityReport::kMaxListedPerCheck)
            report.problems.push_back(std::move(p));
        report.valid = false;
    }
}

} // namespace stratamesh
