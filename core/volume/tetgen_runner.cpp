#include "volume/tetgen_runner.h"

#include "common/error.h"
#include "common/progress.h"
#include "common/translate_noop.h"
#include "io/number_text.h"
#include "model/validity.h"
#include "params/param_tables.h"
#include "volume/child_process.h"
#include "volume/plc.h"
#include "volume/region_winding.h"
#include "volume/tetgen_helper_path.h"
#include "volume/tetgen_poly_writer.h"
#include "volume/tetgen_result_file.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <unistd.h>

namespace stratamesh {

namespace {

namespace fs = std::filesystem;

// A private folder for the PLC, the result and the log, removed with everything in it.
class WorkDirectory {
public:
    WorkDirectory()
    {
        const char *tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/stratamesh-tetgen-XXXXXX";
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        if (!::mkdtemp(buffer.data()))
            throw FileError(pattern, 0,
                            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                          "cannot create a work folder: %1"),
                                        {std::strerror(errno)}});
        m_path = buffer.data();
    }
    ~WorkDirectory()
    {
        std::error_code ignored;
        fs::remove_all(m_path, ignored);
    }
    WorkDirectory(const WorkDirectory &) = delete;
    WorkDirectory &operator=(const WorkDirectory &) = delete;
    std::string file(const char *name) const { return m_path + "/" + name; }

private:
    std::string m_path;
};

bool isExecutable(const std::string &path)
{
    return !path.empty() && ::access(path.c_str(), X_OK) == 0 && !fs::is_directory(path);
}

std::string signalName(int signal)
{
    const char *abbrev = sigabbrev_np(signal);
    return "signal " + std::to_string(signal) + (abbrev ? std::string(", SIG") + abbrev : "");
}

std::string secondsText(double s)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f s", s);
    return buffer;
}

// invalid_input when checkValidity finds what TetGen cannot take: intersecting triangles, one
// triangle twice, and distinct points TetGen would merge (which makes either of the first two).
bool rejectInvalidModel(const Model &model, Progress &progress, TetgenResult &result)
{
    struct Rejected {
        const char *check;
        const char *what;
    };
    static const Rejected rejected[] = {
        {validity_check::surfaceIntersection, "pairs of intersecting triangles"},
        {validity_check::duplicateTriangle, "triangles on two surfaces or twice on one"},
        {validity_check::closeVertices,
         "pairs of distinct points closer than TetGen's merge tolerance (1e-8 of the bounding box "
         "diagonal)"},
    };
    const ValidityReport report = checkValidity(model, progress);
    std::set<std::string> surfaces;
    std::string message;
    for (const Rejected &r : rejected) {
        const std::size_t count = report.count(r.check);
        if (count == 0)
            continue;
        std::set<std::string> groups;
        for (const ValidityProblem &p : report.problems) {
            if (p.check != r.check)
                continue;
            std::string names;
            for (const std::string &e : p.entities) {
                surfaces.insert(e);
                names += (names.empty() ? "" : " and ") + e;
            }
            groups.insert(names);
        }
        std::string listed;
        for (const std::string &g : groups)
            listed += (listed.empty() ? "" : "; ") + g;
        message += (message.empty() ? "" : ", ") + std::to_string(count) + " " + r.what + " ("
                   + listed + ")";
    }
    if (message.empty())
        return false;
    result.outcome = TetgenOutcome::InvalidInput;
    result.message = "TetGen was not run: " + message;
    result.surfaces.assign(surfaces.begin(), surfaces.end());
    return true;
}

struct RawMesh {
    std::vector<Vec3> points;
    std::vector<std::array<std::int32_t, 5>> tets;  // 4 points, attribute
    std::vector<std::array<std::int32_t, 4>> faces; // 3 points, marker
};

// Reads the helper's result file; an empty string on success, else what is wrong with it.
std::string readResult(const std::string &path, RawMesh &raw)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return "the helper wrote no result";
    tetgen_result::Header header, expected;
    in.read(reinterpret_cast<char *>(&header), sizeof header);
    if (!in || std::memcmp(header.magic, expected.magic, sizeof header.magic) != 0)
        return "the helper's result has no valid header";
    in.seekg(0, std::ios::end);
    const auto size = static_cast<std::int64_t>(in.tellg());
    if (header.points < 0 || header.tets < 0 || header.faces < 0
        || size
               != static_cast<std::int64_t>(sizeof header) + header.points * 24 + header.tets * 20
                      + header.faces * 16)
        return "the helper's result has the wrong size";
    in.seekg(sizeof header);
    raw.points.resize(header.points);
    for (Vec3 &p : raw.points)
        in.read(reinterpret_cast<char *>(p.data()), 3 * sizeof(double));
    raw.tets.resize(header.tets);
    in.read(reinterpret_cast<char *>(raw.tets.data()), header.tets * 20);
    raw.faces.resize(header.faces);
    in.read(reinterpret_cast<char *>(raw.faces.data()), header.faces * 16);
    if (!in)
        return "the helper's result could not be read";
    for (const auto &t : raw.tets)
        for (int k = 0; k < 4; ++k)
            if (t[k] < 0 || t[k] >= header.points)
                return "a tet of the helper's result has a point id out of range";
    for (const auto &f : raw.faces)
        for (int k = 0; k < 3; ++k)
            if (f[k] < 0 || f[k] >= header.points)
                return "a face of the helper's result has a point id out of range";
    return {};
}

void buildMesh(const Model &model, const RawMesh &raw, TetgenResult &result)
{
    VolumeMesh &mesh = result.mesh;
    mesh.name = model.name;
    mesh.zPositiveDepth = model.zPositiveDepth;
    mesh.points = raw.points;
    const int regionCount = static_cast<int>(model.regions.size());
    for (const Region &r : model.regions) {
        mesh.regionNames.push_back(r.name);
        mesh.regionBoundaries.push_back(r.boundaries);
    }
    for (const Surface &s : model.surfaces)
        mesh.surfaces.push_back({s.name, s.featureName, s.type});
    mesh.cells.reserve(raw.tets.size());
    mesh.cellRegion.reserve(raw.tets.size());
    // Attributes above the seeded ones number subdomains TetGen found without a seed (a region in
    // two pieces): one region each, found from a few of their roundest tets.
    std::map<int, std::vector<std::size_t>> unseeded;
    auto centroid = [&](const Cell &c) {
        return Vec3((mesh.points[c.nodes[0]] + mesh.points[c.nodes[1]] + mesh.points[c.nodes[2]]
                     + mesh.points[c.nodes[3]])
                    / 4.0);
    };
    for (const auto &t : raw.tets) {
        Cell cell = Cell::tet(t[0], t[1], t[2], t[3]);
        if (signedVolume(mesh, cell) < 0)
            std::swap(cell.nodes[1], cell.nodes[2]);
        int region = t[4] - 1;
        if (region >= regionCount) {
            unseeded[t[4]].push_back(mesh.cells.size());
        } else if (region < 0) {
            // TetGen with Y leaves attribute 0 where it dropped boundary Steiner points.
            ++result.tetsLocatedByCentroid;
            region = locateRegion(model, centroid(cell));
            if (region < 0)
                ++result.tetsWithoutRegion;
        }
        mesh.cells.push_back(cell);
        mesh.cellRegion.push_back(region);
    }
    for (auto &[attribute, cells] : unseeded) {
        auto roundness = [&](std::size_t c) {
            const Cell &cell = mesh.cells[c];
            double faces = 0.0;
            for (const Triangle &f : outwardTriangleFaces(cell))
                faces += (mesh.points[f[1]] - mesh.points[f[0]])
                             .cross(mesh.points[f[2]] - mesh.points[f[0]])
                             .norm();
            return faces > 0 ? signedVolume(mesh, cell) / faces : 0.0; // ∝ inradius
        };
        const std::size_t probes = std::min<std::size_t>(cells.size(), 5);
        std::partial_sort(
            cells.begin(), cells.begin() + probes, cells.end(),
            [&](std::size_t a, std::size_t b) { return roundness(a) > roundness(b); });
        std::map<int, int> votes;
        for (std::size_t i = 0; i < probes; ++i)
            if (const int r = locateRegion(model, centroid(mesh.cells[cells[i]])); r >= 0)
                ++votes[r];
        int region = -1;
        for (const auto &[r, n] : votes)
            if (region < 0 || n > votes[region])
                region = r;
        for (std::size_t c : cells)
            mesh.cellRegion[c] = region;
        result.tetsLocatedByCentroid += cells.size();
        if (region < 0)
            result.tetsWithoutRegion += cells.size();
    }
    const int surfaceCount = static_cast<int>(model.surfaces.size());
    for (const auto &f : raw.faces) {
        mesh.triangles.push_back({f[0], f[1], f[2]});
        mesh.triangleSurface.push_back(f[3] >= 1 && f[3] <= surfaceCount ? f[3] - 1 : -1);
    }
}

void classifyFailure(const ChildExit &exit, const TetgenParams &params, const std::string &logPath,
                     TetgenResult &result)
{
    std::string helperLine;
    std::vector<std::string> tetgenLines;
    for (const std::string &line : lastLines(logPath, 40)) {
        if (line.rfind(tetgen_result::kHelperPrefix, 0) == 0)
            helperLine = line.substr(std::strlen(tetgen_result::kHelperPrefix));
        else if (line.rfind("stratamesh-tetgen: ", 0) == 0) // the C library's assert message
            tetgenLines.push_back(line.substr(std::strlen("stratamesh-tetgen: ")));
        else
            tetgenLines.push_back(line);
    }
    if (!tetgenLines.empty())
        result.lastOutput = tetgenLines.back();
    // TetGen follows a message with detail lines ("1st: [3,4,5] 7", "2nd: ..."): quote them all.
    std::string quoted;
    std::size_t first = tetgenLines.size();
    while (first > 0 && first + 4 > tetgenLines.size()) {
        --first;
        const std::string &line = tetgenLines[first];
        if (!(line.rfind("1st", 0) == 0 || line.rfind("2nd", 0) == 0 || line.rfind("[", 0) == 0))
            break;
    }
    for (std::size_t i = first; i < tetgenLines.size(); ++i)
        quoted += (quoted.empty() ? "" : " ") + tetgenLines[i];
    if (quoted.size() > 400)
        quoted = quoted.substr(0, 400) + "...";
    const std::string tail = quoted.empty() ? "" : ": " + quoted;
    const std::string after = " after " + secondsText(exit.seconds);
    const bool outOfMemoryText = result.lastOutput.find("Out of memory") != std::string::npos
                                 || result.lastOutput.find("bad_alloc") != std::string::npos;
    switch (exit.kind) {
    case ChildExit::Kind::TimedOut:
        result.outcome = TetgenOutcome::TimedOut;
        result.message = "TetGen did not finish within the time limit of "
                         + secondsText(params.timeLimitSeconds) + tail;
        return;
    case ChildExit::Kind::SpawnFailed:
        result.outcome = TetgenOutcome::Aborted;
        result.message = exit.message;
        return;
    case ChildExit::Kind::Signalled:
        // The CPU-time backstop of child_process.h: the wall-clock limit was missed.
        if (exit.signal == SIGXCPU) {
            result.outcome = TetgenOutcome::TimedOut;
            result.message = "TetGen exceeded its CPU time limit" + after + tail;
        } else if (exit.signal == SIGKILL || exit.signal == SIGTERM || exit.signal == SIGINT
                   || exit.signal == SIGHUP) {
            result.outcome = TetgenOutcome::Killed;
            result.message =
                "the TetGen helper was killed (" + signalName(exit.signal) + ")" + after;
        } else if (outOfMemoryText) {
            result.outcome = TetgenOutcome::OutOfMemory;
            result.message = "TetGen ran out of memory" + after + tail;
        } else {
            result.outcome = TetgenOutcome::Aborted;
            result.message = "TetGen crashed (" + signalName(exit.signal) + ")" + after + tail;
        }
        return;
    case ChildExit::Kind::Exited:
        if (exit.exitCode == 9 || exit.exitCode == 11 || outOfMemoryText) {
            result.outcome = TetgenOutcome::OutOfMemory;
            result.message =
                "TetGen ran out of memory" + after
                + (params.memoryLimitMB > 0 ? " (limit " + doubleText(params.memoryLimitMB) + " MB)"
                                            : std::string())
                + tail;
        } else {
            result.outcome = TetgenOutcome::Aborted;
            result.message =
                "TetGen stopped" + after
                + (helperLine.empty() ? " with exit status " + std::to_string(exit.exitCode)
                                      : " with " + helperLine)
                + tail;
        }
        return;
    case ChildExit::Kind::Cancelled:
        break;
    }
}

} // namespace

const char *tetgenOutcomeName(TetgenOutcome outcome)
{
    switch (outcome) {
    case TetgenOutcome::Ok:
        return "ok";
    case TetgenOutcome::Aborted:
        return "aborted";
    case TetgenOutcome::TimedOut:
        return "timed_out";
    case TetgenOutcome::OutOfMemory:
        return "out_of_memory";
    case TetgenOutcome::Killed:
        return "killed";
    case TetgenOutcome::InvalidInput:
        return "invalid_input";
    }
    return "aborted";
}

std::string tetgenSwitches(const TetgenParams &params)
{
    std::string s = "p";
    if (params.quality > 0)
        s += "q" + doubleText(params.quality);
    if (params.maxVolume > 0)
        s += "a" + doubleText(params.maxVolume);
    s += "A";
    if (!params.refineSurfaces)
        s += "Y";
    if (params.noMerge)
        s += "M";
    return s;
}

std::string findTetgenHelper()
{
    if (const char *env = std::getenv("STRATAMESH_TETGEN_HELPER"); env && isExecutable(env))
        return env;
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        for (const fs::path &candidate :
             {exe.parent_path() / "stratamesh-tetgen",
              exe.parent_path().parent_path() / "bin" / "stratamesh-tetgen"})
            if (isExecutable(candidate.string()))
                return candidate.string();
    }
    if (isExecutable(STRATAMESH_TETGEN_BUILD_PATH))
        return STRATAMESH_TETGEN_BUILD_PATH;
    return {};
}

TetgenResult runTetgen(const Model &model, const TetgenParams &params, Progress &progress)
{
    return runTetgen(model, {}, params, progress);
}

TetgenResult runTetgen(const Model &model, const std::vector<Vec3> &holes,
                       const TetgenParams &params, Progress &progress)
{
    TetgenResult result;
    result.switches = tetgenSwitches(params);
    if (!(params.quality >= 0) || !(params.maxVolume >= 0) || !(params.timeLimitSeconds >= 0)
        || !(params.memoryLimitMB >= 0))
        throw InputError(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "TetGen parameters must be finite and not negative"),
                        {}});
    checkParams(tetgenParamTable(), params);

    progress.tick(0.0, "checking the model for TetGen");
    Progress checking = progressRange(progress, 0.0, 0.2);
    Plc plc;
    try {
        if (params.checkInput && rejectInvalidModel(model, checking, result))
            return result;
        plc = buildPlc(model);
        plc.holes = holes;
    } catch (const InputError &e) { // no topology (NaN, bad ids), a region without an inside
        result.outcome = TetgenOutcome::InvalidInput;
        result.message = std::string("TetGen was not run: ") + e.what();
        return result;
    }
    const std::string helper = params.helperPath.empty() ? findTetgenHelper() : params.helperPath;
    if (!isExecutable(helper)) {
        result.outcome = TetgenOutcome::Aborted;
        result.message = "the TetGen helper stratamesh-tetgen was not found"
                         + (helper.empty() ? std::string() : " at " + helper);
        return result;
    }

    std::unique_ptr<WorkDirectory> work;
    std::string poly, output, log;
    try { // a full or read-only temporary folder
        work = std::make_unique<WorkDirectory>();
        poly = work->file("plc.poly");
        output = work->file("mesh.tets");
        log = work->file("tetgen.log");
        writeTetgenPoly(plc, poly);
    } catch (const FileError &e) {
        result.outcome = TetgenOutcome::Aborted;
        result.message = std::string("TetGen was not run: ") + e.what();
        return result;
    }
    Progress meshing = progressRange(progress, 0.2, 0.95);
    const ChildExit exit = runChild({helper, result.switches, poly, output}, log,
                                    {params.timeLimitSeconds, params.memoryLimitMB}, meshing,
                                    "TetGen " + result.switches, params.onStarted);
    result.seconds = exit.seconds;
    result.exitCode = exit.exitCode;
    result.signal = exit.signal;
    if (exit.kind == ChildExit::Kind::Cancelled)
        throw Cancelled();
    if (exit.kind != ChildExit::Kind::Exited || exit.exitCode != 0) {
        classifyFailure(exit, params, log, result);
        return result;
    }
    RawMesh raw;
    if (const std::string problem = readResult(output, raw); !problem.empty()) {
        result.outcome = TetgenOutcome::Aborted;
        result.message = problem;
        return result;
    }
    progress.tick(1.0, "reading the tetrahedra");
    buildMesh(model, raw, result);
    result.outcome = TetgenOutcome::Ok;
    return result;
}

} // namespace stratamesh
