#include "hybrid/hybrid_mesher.h"

#include "common/error.h"
#include "complexity/box_cvt.h"
#include "complexity/box_elements.h"
#include "hybrid/cell_faces.h"
#include "hybrid/surface_sites.h"
#include "hybrid/vertex_dual_cells.h"
#include "io/mesh_writer.h"
#include "model/region_volume.h"
#include "model/surface_edges.h"
#include "model/topology.h"
#include "params/param_tables.h"
#include "remesh/surface_remesher.h"
#include "remesh/triangle_intersections.h"
#include "volume/plc.h"
#include "volume/region_winding.h"
#include "volume/tet_quality.h"
#include "volume/tetgen_poly_writer.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace stratamesh {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t)
{
    return std::chrono::duration<double>(Clock::now() - t).count();
}

using PointKey = std::tuple<double, double, double>;
PointKey keyOf(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

// The hybrid cells of one fill attempt and what TetGen made of the rest.
struct Fill {
    std::vector<Cell> cells; // kept thesis cells, then transition pyramids
    std::vector<int> region;
    std::vector<int> owner; // for a pyramid, the thesis cell whose quad it covers; else itself
    std::vector<Vec3> apexes;
    std::size_t pyramids = 0;
    std::size_t loweredPyramids = 0; // apexes brought down to clear a neighbouring facet
    std::set<int> conflicts;         // kept cells whose faces still cross another facet
    TetgenResult tetgen;
};

// Transition pyramids stand out of the thin layers and may cross a neighbour's pyramid, a surface
// or another cell. A pyramid whose sides cross another facet is lowered, halving its height up to
// three times; crossings that remain name the kept cells to drop before TetGen sees them (rather
// than every cell with a pyramid, which emptied modelA1@5000 at pyramid height 0.3).
void resolveCrossings(const Model &remesh, const std::vector<Vec3> &basePoints,
                      std::size_t keptCount, const std::vector<Triangle> &facets,
                      const std::vector<int> &facetCell, const std::vector<Vec3> &apexBase,
                      std::vector<Vec3> apexUp, Fill &fill)
{
    std::vector<Triangle> soup;
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s)
        for (const Triangle &t : remesh.surfaces[s].triangles) {
            const auto &g = remesh.surfaceVertexToGlobal[s];
            soup.push_back({g[t[0]], g[t[1]], g[t[2]]});
        }
    const std::size_t surfaceCount = soup.size();
    soup.insert(soup.end(), facets.begin(), facets.end());
    auto cellOf = [&](int t) {
        return t < static_cast<int>(surfaceCount) ? -1 : facetCell[t - surfaceCount];
    };
    std::set<int> lowered;
    const int halvings = 3;
    for (int round = 0; round <= halvings; ++round) {
        std::vector<Vec3> points = basePoints;
        points.insert(points.end(), fill.apexes.begin(), fill.apexes.end());
        std::set<int> crossingPyramids, crossingCells;
        for (const auto &[i, j] : findIntersectingTriangles(points, soup))
            for (int c : {cellOf(i), cellOf(j)}) {
                if (c < 0)
                    continue;
                (c >= static_cast<int>(keptCount) ? crossingPyramids : crossingCells).insert(c);
            }
        if (crossingPyramids.empty() || round == halvings) {
            for (int c : crossingPyramids)
                fill.conflicts.insert(fill.owner[c]);
            for (int c : crossingCells)
                fill.conflicts.insert(fill.owner[c]);
            break;
        }
        for (int c : crossingPyramids) {
            const std::size_t k = c - keptCount;
            apexUp[k] *= 0.5;
            fill.apexes[k] = apexBase[k] + apexUp[k];
            lowered.insert(c);
        }
    }
    fill.loweredPyramids = lowered.size();
}

// Builds the cavity model: the remesh triangles no kept cell lies on, plus per region a surface
// of the cell faces that face the cavity (normals into it), and runs TetGen on it.
// Points: the remesh's, then the interior sites of the vertex-dual cells (basePoints), then apexes.
void fillCavities(const Model &remesh, const std::vector<Vec3> &basePoints,
                  const std::vector<Cell> &kept, const std::vector<int> &keptRegion,
                  const HybridParams &params, const std::string &polyPath, Fill &fill,
                  Progress &progress)
{
    const std::vector<Vec3> &p = basePoints;
    const int nPoints = static_cast<int>(p.size());
    fill.cells = kept;
    fill.region = keptRegion;
    fill.owner.resize(kept.size());
    for (std::size_t c = 0; c < kept.size(); ++c)
        fill.owner[c] = static_cast<int>(c);
    std::set<std::array<int, 3>> surfaceKeys;
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s)
        for (const Triangle &t : remesh.surfaces[s].triangles) {
            const auto &g = remesh.surfaceVertexToGlobal[s];
            surfaceKeys.insert(sortedTriangle(g[t[0]], g[t[1]], g[t[2]]));
        }
    std::map<std::array<int, 4>, std::vector<std::pair<int, CellFace>>> faces;
    for (std::size_t c = 0; c < kept.size(); ++c)
        for (const CellFace &f : outwardFaces(kept[c]))
            faces[faceKey(f)].push_back({static_cast<int>(c), f});
    // Remesh triangles a cell lies on -> the cell's region (-1: cells on both sides).
    std::map<std::array<int, 3>, int> usedSurface;
    std::vector<std::vector<std::array<int, 3>>> exposed(remesh.regions.size());
    std::vector<Triangle> facets;       // the cavity's cell facets, for the crossing test below
    std::vector<int> facetCell;         // index in fill.cells
    std::vector<Vec3> apexBase, apexUp; // per pyramid: quad centroid, unit normal times height
    for (const auto &[key, uses] : faces) {
        const auto &[c, f] = uses.front();
        const int r = keptRegion[c];
        if (!f.isQuad()) {
            const auto k = sortedTriangle(f.nodes[0], f.nodes[1], f.nodes[2]);
            if (surfaceKeys.count(k))
                usedSurface[k] = uses.size() == 1 ? r : -1;
            else if (uses.size() == 1) {
                exposed[r].push_back({f.nodes[0], f.nodes[1], f.nodes[2]});
                facets.push_back({f.nodes[0], f.nodes[1], f.nodes[2]});
                facetCell.push_back(c);
            }
            continue;
        }
        if (uses.size() != 1)
            continue; // shared by two cells (more is caught by the final check)
        // A transition pyramid on the quad, apex on the cavity side.
        const Vec3 &a = p[f.nodes[0]], &b = p[f.nodes[1]], &cc = p[f.nodes[2]], &d = p[f.nodes[3]];
        const Vec3 n = (cc - a).cross(d - b);
        const double area = 0.5 * n.norm();
        apexBase.push_back((a + b + cc + d) / 4.0);
        apexUp.push_back(n.normalized() * params.pyramidHeightRatio * std::sqrt(area));
        const int apexId = nPoints + static_cast<int>(fill.apexes.size());
        fill.apexes.push_back(apexBase.back() + apexUp.back());
        fill.cells.push_back(Cell::pyramid(f.nodes[0], f.nodes[1], f.nodes[2], f.nodes[3], apexId));
        fill.region.push_back(r);
        fill.owner.push_back(c);
        ++fill.pyramids;
        for (int k = 0; k < 4; ++k) {
            exposed[r].push_back({f.nodes[k], f.nodes[(k + 1) % 4], apexId});
            facets.push_back({f.nodes[k], f.nodes[(k + 1) % 4], apexId});
            facetCell.push_back(static_cast<int>(fill.cells.size()) - 1);
        }
    }
    resolveCrossings(remesh, basePoints, kept.size(), facets, facetCell, apexBase, apexUp, fill);
    if (!fill.conflicts.empty()) {
        fill.tetgen = {};
        fill.tetgen.outcome = TetgenOutcome::InvalidInput;
        fill.tetgen.message = "TetGen was not run: " + std::to_string(fill.conflicts.size())
                              + " cells cross a neighbouring facet";
        return;
    }

    // The cavity model, on points 0..nPoints-1 of the remesh and the apexes after them.
    auto pointAt = [&](int id) -> const Vec3 & {
        return id < nPoints ? p[id] : fill.apexes[id - nPoints];
    };
    Model cavity;
    cavity.name = remesh.name + "_cavity";
    std::vector<int> surfaceMap(remesh.surfaces.size(), -1);
    auto addSurface = [&](Surface s, const std::vector<std::array<int, 3>> &tris) {
        std::map<int, int> local;
        for (const auto &t : tris) {
            Triangle lt;
            for (int k = 0; k < 3; ++k) {
                auto [it, fresh] = local.emplace(t[k], static_cast<int>(s.vertices.size()));
                if (fresh)
                    s.vertices.push_back(pointAt(t[k]));
                lt[k] = it->second;
            }
            s.triangles.push_back(lt);
        }
        cavity.surfaces.push_back(std::move(s));
        return static_cast<int>(cavity.surfaces.size()) - 1;
    };
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s) {
        std::vector<std::array<int, 3>> tris;
        const auto &g = remesh.surfaceVertexToGlobal[s];
        for (const Triangle &t : remesh.surfaces[s].triangles) {
            auto used = usedSurface.find(sortedTriangle(g[t[0]], g[t[1]], g[t[2]]));
            if (used == usedSurface.end()) {
                tris.push_back({g[t[0]], g[t[1]], g[t[2]]});
                continue;
            }
            // A cell lies on it on one side: it still bounds the cavity of the other regions.
            for (int other : remesh.surfaces[s].regions) {
                if (used->second < 0 || other == used->second)
                    continue;
                for (const RegionSide &side : remesh.regions[other].boundaries)
                    if (side.surface == static_cast<int>(s)) {
                        if (side.positive)
                            exposed[other].push_back({g[t[0]], g[t[1]], g[t[2]]});
                        else
                            exposed[other].push_back({g[t[0]], g[t[2]], g[t[1]]});
                        break;
                    }
            }
        }
        if (tris.empty())
            continue;
        Surface copy;
        copy.name = remesh.surfaces[s].name;
        copy.featureName = remesh.surfaces[s].featureName;
        copy.type = remesh.surfaces[s].type;
        surfaceMap[s] = addSurface(std::move(copy), tris);
    }
    std::vector<int> regionMap; // cavity region -> remesh region
    for (std::size_t r = 0; r < remesh.regions.size(); ++r) {
        Region region;
        region.name = remesh.regions[r].name;
        for (const RegionSide &side : remesh.regions[r].boundaries)
            if (surfaceMap[side.surface] >= 0)
                region.boundaries.push_back({surfaceMap[side.surface], side.positive});
        if (!exposed[r].empty()) {
            Surface s;
            s.name = "hybrid_cells_" + std::to_string(r);
            s.featureName = s.name;
            s.type = FeatureType::Unknown;
            region.boundaries.push_back({addSurface(std::move(s), exposed[r]), true});
        }
        if (region.boundaries.empty())
            continue; // the cells fill the region
        cavity.regions.push_back(region);
        regionMap.push_back(static_cast<int>(r));
    }
    if (cavity.regions.empty()) {
        fill.tetgen = {};
        fill.tetgen.outcome = TetgenOutcome::Ok;
        return;
    }
    // One hole point inside every hybrid cell: TetGen leaves their zones empty, so its tets meet
    // the cells only across the cavity facets, which it keeps (Y).
    std::vector<Vec3> holes;
    holes.reserve(fill.cells.size());
    for (const Cell &cell : fill.cells) {
        Vec3 g = Vec3::Zero();
        for (int k = 0; k < cell.size(); ++k)
            g += pointAt(cell.nodes[k]);
        holes.push_back(g / cell.size());
    }
    try {
        const Model topology = recoverTopology(cavity);
        if (!polyPath.empty()) {
            Plc plc = buildPlc(topology);
            plc.holes = holes;
            writeTetgenPoly(plc, polyPath);
        }
        fill.tetgen = runTetgen(topology, holes, params.tetgen, progress);
    } catch (const InputError &e) {
        fill.tetgen = {};
        fill.tetgen.outcome = TetgenOutcome::InvalidInput;
        fill.tetgen.message = e.what();
        return;
    }
    // A tet of no cavity region (TetGen's attribute 0) is located in the remesh, whose regions
    // are closed; one left in a cell's zone would overlap it, which the check finds.
    VolumeMesh &tets = fill.tetgen.mesh;
    std::vector<Cell> cells;
    std::vector<int> regions;
    for (std::size_t c = 0; c < tets.cells.size(); ++c) {
        int region = tets.cellRegion[c] >= 0 ? regionMap[tets.cellRegion[c]] : -1;
        if (region < 0) {
            const Cell &t = tets.cells[c];
            region = locateRegion(remesh, (tets.points[t.nodes[0]] + tets.points[t.nodes[1]]
                                           + tets.points[t.nodes[2]] + tets.points[t.nodes[3]])
                                              / 4.0);
        }
        cells.push_back(tets.cells[c]);
        regions.push_back(region);
    }
    tets.cells = std::move(cells);
    tets.cellRegion = std::move(regions);
}

// The final mesh: remesh points, apexes, TetGen's own points; thesis cells, pyramids, tets; the
// remesh triangles with their surfaces.
VolumeMesh assemble(const Model &remesh, const std::vector<Vec3> &basePoints, const Fill &fill)
{
    VolumeMesh m;
    m.name = remesh.name;
    m.zPositiveDepth = remesh.zPositiveDepth;
    m.points = basePoints;
    m.points.insert(m.points.end(), fill.apexes.begin(), fill.apexes.end());
    std::map<PointKey, int> known;
    for (std::size_t i = 0; i < m.points.size(); ++i)
        known.emplace(keyOf(m.points[i]), static_cast<int>(i));
    m.cells = fill.cells;
    m.cellRegion = fill.region;
    const VolumeMesh &t = fill.tetgen.mesh;
    std::vector<int> map(t.points.size());
    for (std::size_t i = 0; i < t.points.size(); ++i) {
        auto [it, fresh] = known.emplace(keyOf(t.points[i]), static_cast<int>(m.points.size()));
        if (fresh)
            m.points.push_back(t.points[i]);
        map[i] = it->second;
    }
    for (std::size_t c = 0; c < t.cells.size(); ++c) {
        Cell cell = t.cells[c];
        for (int k = 0; k < 4; ++k)
            cell.nodes[k] = map[cell.nodes[k]];
        m.cells.push_back(cell);
        m.cellRegion.push_back(t.cellRegion[c]);
    }
    for (const Region &r : remesh.regions) {
        m.regionNames.push_back(r.name);
        m.regionBoundaries.push_back(r.boundaries);
    }
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s) {
        const Surface &surface = remesh.surfaces[s];
        m.surfaces.push_back({surface.name, surface.featureName, surface.type});
        for (const Triangle &tri : surface.triangles) {
            const auto &g = remesh.surfaceVertexToGlobal[s];
            m.triangles.push_back({g[tri[0]], g[tri[1]], g[tri[2]]});
            m.triangleSurface.push_back(static_cast<int>(s));
        }
    }
    // Contact lines and corners, as the other volume meshes carry them.
    for (std::size_t l = 0; l < remesh.lines.size(); ++l) {
        const Line &line = remesh.lines[l];
        m.lineNames.push_back(line.name);
        const std::size_t n = line.vertices.size();
        for (std::size_t k = 0; k + 1 < n + (line.closed ? 1 : 0); ++k) {
            m.edges.push_back({line.vertices[k], line.vertices[(k + 1) % n]});
            m.edgeLine.push_back(static_cast<int>(l));
        }
    }
    for (const Corner &c : remesh.corners)
        m.corners.push_back(c.vertex);
    return m;
}

void dropCells(const std::set<int> &remove, std::vector<Cell> &kept, std::vector<int> &keptRegion,
               std::vector<char> &keptVertexDual)
{
    std::vector<Cell> next;
    std::vector<int> nextRegion;
    std::vector<char> nextVertexDual;
    for (std::size_t c = 0; c < kept.size(); ++c)
        if (!remove.count(static_cast<int>(c))) {
            next.push_back(kept[c]);
            nextRegion.push_back(keptRegion[c]);
            nextVertexDual.push_back(keptVertexDual[c]);
        }
    kept = std::move(next);
    keptRegion = std::move(nextRegion);
    keptVertexDual = std::move(nextVertexDual);
}

// Fills after a valid one whose slivers lie against cut-vertex tets (each drops those tets).
constexpr int kSliverRounds = 3;

// The kept cut-vertex tets (keptVertexDual 2) sharing a point with a fill tet that is a sliver.
// The mesh's first `fillCells` cells are the kept ones then the pyramids, in kept's order.
std::set<int> cutTetsBesideFillSlivers(const VolumeMesh &mesh, std::size_t fillCells,
                                       const std::vector<Cell> &kept,
                                       const std::vector<char> &keptVertexDual)
{
    std::map<int, std::vector<int>> cutAt; // node -> cut-vertex tets
    for (std::size_t c = 0; c < kept.size(); ++c)
        if (keptVertexDual[c] == 2)
            for (int k = 0; k < 4; ++k)
                cutAt[kept[c].nodes[k]].push_back(static_cast<int>(c));
    std::set<int> out;
    if (cutAt.empty())
        return out;
    for (std::size_t c = fillCells; c < mesh.cells.size(); ++c) {
        const auto &n = mesh.cells[c].nodes;
        const auto angles = dihedralAnglesDeg(mesh.points[n[0]], mesh.points[n[1]],
                                              mesh.points[n[2]], mesh.points[n[3]]);
        if (*std::min_element(angles.begin(), angles.end()) >= kSliverDihedralDeg)
            continue;
        for (int k = 0; k < 4; ++k) {
            auto it = cutAt.find(n[k]);
            if (it != cutAt.end())
                out.insert(it->second.begin(), it->second.end());
        }
    }
    return out;
}

} // namespace

HybridResult buildHybridMesh(const Model &input, const HybridParams &params, Progress &progress)
{
    checkParams(hybridParamTable(), params);
    if (input.surfaces.empty())
        throw InputError("hybrid mesh: the model has no surface");
    HybridResult result;
    const auto start = Clock::now();
    const Model model = input.vertices.empty() ? recoverTopology(input) : input;

    auto t = Clock::now();
    BoxCvtParams cvtParams;
    cvtParams.sites = params.sites;
    cvtParams.iterations = params.cvtIterations;
    cvtParams.seed = params.seed;
    // Each stage its share of the bar (weights: the stage times of modelA1 at 5000 sites), so that
    // the bar moves through the whole run instead of filling during the CVT.
    ProgressSteps steps(progress, {65.0, 8.0, 4.0, 1.0, 22.0});
    BoxCvt cvt;
    {
        Progress part = steps.step(0, "Volume CVT");
        cvt = runBoxCvt(modelBounds(model), cvtParams, part);
    }
    result.timings.cvtSeconds = since(t);
    t = Clock::now();
    Progress surfacePart = steps.step(1, "Surface sites");
    const std::vector<Vec3> sites =
        params.surfaceIterations > 0
            ? optimizeSurfaceSites(model, cvt.sites, params.surfaceIterations, surfacePart).sites
            : cvt.sites;
    result.timings.surfaceSitesSeconds = since(t);

    // Triangles must stay dual to restricted Voronoi vertices: no flips, smoothing or refinement.
    t = Clock::now();
    RemeshParams remeshParams;
    remeshParams.flips = false;
    remeshParams.smoothingPasses = 0;
    remeshParams.refinementRounds = 0;
    Progress remeshPart = steps.step(2, "Surface remesh");
    RemeshResult remeshed = remeshWithSites(model, sites, remeshParams, remeshPart);
    if (!remeshed.validity.valid) {
        // No TetGen fill can stand on crossing or unsealed surfaces (fault networks at some
        // resolutions): remesh from the same sites with the chapter-4 repairs (flips, smoothing,
        // refinement). Triangles that stay dual still pair into cells; the others fail the
        // cells' shape and thinness tests and are left to the tets.
        result.remeshRetried = true;
        std::string problems;
        for (const auto &[check, n] : remeshed.validity.counts) {
            result.firstRemeshProblems[check] = n;
            problems += (problems.empty() ? "" : ", ") + std::to_string(n) + " " + check;
        }
        result.repairLog.push_back("surface remesh: the dual remesh is not valid (" + problems
                                   + "); the surfaces are remeshed with the chapter-4 repairs");
        const int surfaceSites = remeshed.siteCount;
        remeshed = remeshWithSites(model, sites, RemeshParams{}, remeshPart);
        if (!remeshed.validity.valid) {
            // Still not valid (an 8-fault network at 1000 volume sites): the chapter-4 remesher's
            // own run at as many surface sites, valid on every model of its test matrix. Its
            // triangles are no longer dual to these sites; cells form only where they still fit.
            RemeshParams own;
            own.sites = std::max(surfaceSites, static_cast<int>(model.surfaces.size()));
            own.seed = params.seed;
            remeshed = remeshModel(model, own, remeshPart);
        }
    }
    result.surfaceRemesh = std::make_shared<const Model>(std::move(remeshed.model));
    const Model &remesh = *result.surfaceRemesh;
    result.remeshSites = remeshed.siteCount;
    result.remeshValid = remeshed.validity.valid;
    result.remeshProblems = remeshed.validity.counts;
    result.timings.remeshSeconds = since(t);

    t = Clock::now();
    steps.step(3, "Thesis cells");
    const std::vector<int> pointSite = nearestSites(remesh.vertices, sites);
    result.segmentDual = buildSegmentDualCells(remesh, pointSite, params.cells);
    result.invalidFound = result.segmentDual.rejectedShape;
    VertexDualParams vertexParams = params.vertexCells;
    vertexParams.pyramidHeightRatio = params.pyramidHeightRatio;
    result.vertexDual =
        buildVertexDualCells(remesh, sites, pointSite, result.segmentDual.cells,
                             static_cast<int>(remesh.vertices.size()), vertexParams);
    std::vector<Vec3> basePoints = remesh.vertices;
    basePoints.insert(basePoints.end(), result.vertexDual.points.begin(),
                      result.vertexDual.points.end());
    result.timings.cellsSeconds = since(t);

    MixedMeshCheckParams check;
    check.maxQuadWarpDegrees = params.cells.maxQuadWarpDegrees;
    check.regionVolumes = regionVolumes(remesh);

    Progress fillStage = steps.step(4, "Fill and check");
    std::vector<Cell> kept = result.segmentDual.cells;
    std::vector<int> keptRegion = result.segmentDual.region;
    std::vector<char> keptVertexDual(kept.size(), 0);
    kept.insert(kept.end(), result.vertexDual.cells.begin(), result.vertexDual.cells.end());
    keptRegion.insert(keptRegion.end(), result.vertexDual.region.begin(),
                      result.vertexDual.region.end());
    keptVertexDual.resize(kept.size(), 1);
    // The cut-vertex tets come last among the vertex-dual cells: 2 tells them apart.
    std::fill(keptVertexDual.end() - static_cast<std::ptrdiff_t>(result.vertexDual.cutKept),
              keptVertexDual.end(), 2);
    int sliverRounds = 0;
    for (int round = 0;; ++round) {
        // Without thesis cells the fill is the last resort already.
        const bool lastResort = round > params.repairRounds || kept.empty();
        if (lastResort) {
            result.repaired += kept.size();
            kept.clear();
            keptRegion.clear();
            keptVertexDual.clear();
            result.fellBackToTetgen = true;
        }
        t = Clock::now();
        Fill fill;
        // Rounds are few and each shorter than the last: round r gets [1 - 2^-r, 1 - 2^-(r+1)].
        const int attempt = round + sliverRounds;
        const double from = 1.0 - std::ldexp(1.0, -attempt),
                     to = 1.0 - std::ldexp(1.0, -attempt - 1);
        Progress roundPart(fillStage, from, from + 0.8 * (to - from));
        fillCavities(remesh, basePoints, kept, keptRegion, params,
                     attempt == 0 ? params.cavityPolyPath : "", fill, roundPart);
        fillStage.tick(from + 0.8 * (to - from), "mixed-mesh check");
        result.timings.fillSeconds += since(t);
        result.tetgenOutcome = fill.tetgen.outcome;
        result.repairRounds = round;
        std::set<int> remove; // thesis cells to drop before the next round
        std::string firstProblem;
        if (fill.tetgen.outcome == TetgenOutcome::Ok) {
            t = Clock::now();
            VolumeMesh mesh = assemble(remesh, basePoints, fill);
            MixedMeshValidity validity = checkMixedMesh(mesh, check);
            // Fill slivers pressed between cut-vertex tets and the surfaces (four surface points
            // on one face, most often): those tets go and TetGen fills the wider place.
            std::set<int> pressing =
                validity.valid() && !lastResort && sliverRounds < kSliverRounds
                    ? cutTetsBesideFillSlivers(mesh, fill.cells.size(), kept, keptVertexDual)
                    : std::set<int>{};
            result.timings.checkSeconds += since(t);
            if (!pressing.empty()) {
                ++sliverRounds;
                result.repairLog.push_back("fill " + std::to_string(round) + ": "
                                           + std::to_string(pressing.size())
                                           + " cut-vertex tets beside fill slivers dropped");
                dropCells(pressing, kept, keptRegion, keptVertexDual);
                --round; // not a repair: the mesh was valid
                continue;
            }
            if (validity.valid() || lastResort) {
                // Renumbered only now: the repair above matches the mesh's ids with the cells'.
                dropUnusedPoints(mesh);
                result.mesh = std::move(mesh);
                result.validity = std::move(validity);
                result.cutVertexDualKept = static_cast<std::size_t>(
                    std::count(keptVertexDual.begin(), keptVertexDual.end(), 2));
                result.vertexDualKept = result.cutVertexDualKept
                                        + static_cast<std::size_t>(std::count(
                                            keptVertexDual.begin(), keptVertexDual.end(), 1));
                result.segmentDualKept = kept.size() - result.vertexDualKept;
                result.transitionPyramids = fill.pyramids;
                result.loweredPyramids = fill.loweredPyramids;
                result.fillTets = fill.tetgen.mesh.cells.size();
                if (!result.validity.valid())
                    result.message = result.validity.firstProblem;
                if (!result.validity.valid() && !result.remeshValid) {
                    // No fill can mend the surfaces: say where the trouble starts.
                    std::string checks;
                    for (const auto &[check, n] : result.remeshProblems)
                        checks += (checks.empty() ? "" : ", ") + check;
                    result.message =
                        "the surface remesh is not valid (" + checks + "): " + result.message;
                }
                break;
            }
            firstProblem = validity.firstProblem;
            if (!params.cavityPolyPath.empty()) // the fill refused, to look at
                exportVolumeMesh(mesh,
                                 params.cavityPolyPath + ".fill" + std::to_string(round) + ".vtu");
            for (int c : validity.invalidCells)
                if (c < static_cast<int>(fill.cells.size()))
                    remove.insert(fill.owner[c]);
            if (remove.empty()) { // only tets are wrong: drop the cells they touch
                std::set<int> touched;
                for (int c : validity.invalidCells)
                    for (int k = 0; k < mesh.cells[c].size(); ++k)
                        touched.insert(mesh.cells[c].nodes[k]);
                for (std::size_t c = 0; c < fill.cells.size(); ++c)
                    for (int k = 0; k < fill.cells[c].size(); ++k)
                        if (touched.count(fill.cells[c].nodes[k]))
                            remove.insert(fill.owner[c]);
            }
            if (remove.empty()) // a region volume alone is wrong: drop every cell
                for (std::size_t c = 0; c < kept.size(); ++c)
                    remove.insert(static_cast<int>(c));
        } else if (lastResort) {
            result.message = "TetGen: " + fill.tetgen.message;
            break;
        } else if (!fill.conflicts.empty()) {
            remove = fill.conflicts; // cells whose faces cross a neighbour even with low pyramids
        } else {
            // The cavity is not a valid PLC (a pyramid crossing a surface, most often): drop the
            // cells with a transition pyramid, the border row of each thin zone.
            for (std::size_t c = kept.size(); c < fill.cells.size(); ++c)
                remove.insert(fill.owner[c]);
            if (remove.empty()) // then the vertex-dual cells, before the thin-layer ones
                for (std::size_t c = 0; c < kept.size(); ++c)
                    if (keptVertexDual[c])
                        remove.insert(static_cast<int>(c));
            if (remove.empty())
                for (std::size_t c = 0; c < kept.size(); ++c)
                    remove.insert(static_cast<int>(c));
        }
        result.repairLog.push_back("fill " + std::to_string(round) + ": "
                                   + (fill.tetgen.outcome == TetgenOutcome::Ok
                                          ? "check: " + firstProblem
                                          : std::string("TetGen ")
                                                + tetgenOutcomeName(fill.tetgen.outcome) + ": "
                                                + fill.tetgen.message)
                                   + "; " + std::to_string(remove.size()) + " cells dropped");
        result.invalidFound += remove.size();
        result.repaired += remove.size();
        dropCells(remove, kept, keptRegion, keptVertexDual);
    }
    result.timings.totalSeconds = since(start);
    return result;
}

} // namespace stratamesh
