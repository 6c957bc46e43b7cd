#include "remesh/surface_remesher.h"

#include "common/error.h"
#include "complexity/element_sizes.h"
#include "cvt/cvt_optimizer.h"
#include "cvt/initial_sampling.h"
#include "model/bounding_box.h"
#include "model/topology.h"
#include "params/param_tables.h"
#include "quality/mesh_statistics.h"
#include "remesh/cell_components.h"
#include "remesh/duplicate_separation.h"
#include "remesh/editable_soup.h"
#include "remesh/feature_sizing.h"
#include "remesh/flat_triangles.h"
#include "remesh/input_projector.h"
#include "remesh/ledger_reconciliation.h"
#include "remesh/line_fins.h"
#include "remesh/line_spacing.h"
#include "remesh/mesh_smoothing.h"
#include "remesh/output_model_builder.h"
#include "remesh/output_points.h"
#include "remesh/pocket_repair.h"
#include "remesh/sizing_refinement.h"
#include "remesh/strip_collapse.h"
#include "remesh/strip_rows.h"
#include "remesh/topology_refinement.h"
#include "voronoi/restricted_voronoi.h"
#include "voronoi/restriction_domain.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace stratamesh {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Model withTopology(const Model &input)
{
    if (input.surfaces.empty() || input.triangleCount() == 0)
        throw InputError("remesh: the model has no triangle");
    return input.hasTopology() ? input : recoverTopology(input);
}

// ρ(y) = max(floor, (1 − d(y)/d_max)^exponent), d the distance to the nearest corner (or line
// vertex when there is no corner), per global vertex (thesis Fig 4.19).
std::vector<double> adaptiveDensity(const Model &model, const RemeshParams &params)
{
    std::vector<Vec3> features;
    for (const Corner &c : model.corners)
        features.push_back(model.vertices[c.vertex]);
    if (features.empty())
        for (const Line &l : model.lines)
            for (int v : l.vertices)
                features.push_back(model.vertices[v]);
    if (features.empty())
        return {};
    std::vector<double> d(model.vertices.size(), std::numeric_limits<double>::max());
    double dMax = 0.0;
    for (std::size_t v = 0; v < model.vertices.size(); ++v) {
        for (const Vec3 &f : features)
            d[v] = std::min(d[v], (model.vertices[v] - f).norm());
        dMax = std::max(dMax, d[v]);
    }
    std::vector<double> rho(d.size(), 1.0);
    if (dMax > 0.0)
        for (std::size_t v = 0; v < d.size(); ++v)
            rho[v] = std::max(params.adaptiveFloor,
                              std::pow(1.0 - d[v] / dMax, params.adaptiveExponent));
    return rho;
}

std::string number(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

StripCollapse stripsRemoved(const Model &input, double edgeLength, const RemeshParams &params,
                            SimplificationLedger &ledger, Progress &progress)
{
    const double width = stripWidthLimit(params, edgeLength);
    if (width > 0.0)
        return removeThinStrips(input, width, ledger, progress);
    StripCollapse none;
    none.model = input;
    return none;
}

// The mesh-building half on the model without its thin strips.
RemeshResult meshFromSites(const StripCollapse &collapsed, const std::vector<Vec3> &sites,
                           const RemeshParams &params, SimplificationLedger ledger,
                           Progress &progress)
{
    const auto start = std::chrono::steady_clock::now();
    const Model &input = collapsed.model;
    RemeshResult result;
    result.ledger = std::move(ledger);
    result.strips = collapsed.removed;
    result.sites = sites;
    result.siteCount = static_cast<int>(sites.size());
    // Shares of the mesh-building time measured on modelA5 at 5000 sites.
    ProgressSteps steps(progress, {30, 5, 20, 15, 15, 10, 5});
    const RestrictionDomain domain = makeRestrictionDomain(input);
    RestrictedVoronoiDiagram rvd;
    {
        Progress step = steps.step(0, "restricted Voronoi diagram");
        rvd = computeRestrictedVoronoi(domain, sites, step);
    }
    CellComponents components;
    {
        Progress step = steps.step(1, "cell components");
        components = computeCellComponents(domain, rvd);
    }
    CellPointsParams pointParams;
    pointParams.dResolution = mergeDistance(params);
    pointParams.mergeAllExtraPoints = params.mergeAllExtraPoints;
    CellPoints points;
    {
        Progress step = steps.step(2, "cell points");
        points =
            computeCellPoints(input, domain, rvd, components, pointParams, result.ledger, step);
    }
    OutputMesh mesh;
    mesh.points = points.points;
    {
        Progress step = steps.step(3, "dual faces");
        mesh.triangles = buildDualFaces(domain, rvd, components, points, result.faces, step);
    }
    EditableSoup soup(std::move(mesh));
    {
        Progress step = steps.step(4, "post-processing");
        step.tick(0.0, "fins and valence 3");
        const int fins = removeLineFins(soup);
        const CleanupCounts v3 = removeValence3Vertices(soup, input, result.ledger);
        step.tick(0.2, "degenerate triangles");
        result.cleanup = removeDegenerateTriangles(soup, input, params.cleanup, result.ledger);
        result.cleanup.valence3 = v3.valence3;
        result.cleanup.lineFins = fins;
        step.tick(0.4, "duplicates");
        result.duplicates = separateDuplicateTriangles(soup, input, result.ledger);
        step.tick(0.6, "flips");
        spaceLineVertices(soup);
        if (params.flips)
            result.cleanup.flips += improveByFlips(soup);
        if (params.smoothingPasses > 0) {
            Progress smoothingStep(step, 0.7, 0.9, "smoothing");
            InputProjector projector(input);
            SmoothingParams smoothing;
            smoothing.passes = params.smoothingPasses;
            result.cleanup.relaxed = relaxVertices(soup, projector, smoothing, smoothingStep);
            step.tick(0.9, "flips");
            if (params.flips)
                result.cleanup.flips += improveByFlips(soup);
            Progress rows(step, 0.95, 1.0, "strip rows");
            result.cleanup.stripRows = addStripRows(soup, projector, {}, rows);
        }
    }
    {
        Progress step = steps.step(5, "intersections");
        result.intersections = repairIntersections(soup, input, params.repair, result.ledger, step);
    }
    {
        Progress step = steps.step(6, "output model");
        result.model = buildOutputModel(input, soup.result(), result.ledger, step);
    }
    result.timings.meshSeconds = secondsSince(start);
    result.timings.totalSeconds = result.timings.meshSeconds;
    progress.tick(1.0);
    return result;
}

// The validity of a result, after opening the pockets its dual mesh closed (pocket_repair.h).
void checkAndOpenPockets(RemeshResult &result, Progress &progress)
{
    Progress checking(progress, 0.0, 0.5, "checking");
    result.validity = checkValidity(result.model, checking);
    if (result.validity.count(validity_check::regionPocket) == 0)
        return;
    Progress opening(progress, 0.5, 1.0, "opening pockets");
    result.pocketsOpened += repairPockets(result.model, result.validity, opening).opened;
}

// The feature sizing field for an edge length h0, its smallest size raised until it needs at most
// sizingMaxGrowth times the sites of a uniform h0 (features left closer are the refinement
// rounds' or the ledger's).
FeatureSizing fittedSizing(const Model &model, double h0, const RemeshParams &params,
                           Progress &progress)
{
    FeatureSizingParams sp;
    sp.edgeLength = h0;
    sp.lfsFactor = params.lfsFactor;
    sp.gradation = params.sizingGradation;
    sp.minEdgeLength = params.sizingMinFraction * h0;
    sp.dResolution = mergeDistance(params);
    std::vector<double> lfs =
        localFeatureSizes(model, h0 / params.lfsFactor, sp.wedgeSine, progress);
    FeatureSizing sizing = sizingFromLfs(model, lfs, sp);
    while (sizing.siteFactor > params.sizingMaxGrowth && sp.minEdgeLength < h0) {
        sp.minEdgeLength = std::min(h0, 1.5 * sp.minEdgeLength);
        sizing = sizingFromLfs(model, lfs, sp);
    }
    return sizing;
}

} // namespace

int sitesForEdgeLength(double area, double edgeLength)
{
    if (!(edgeLength > 0.0))
        throw InputError("remesh: the target edge length must be positive");
    const ParamInfo &sites = remeshParamTable().info("sites");
    const int most = static_cast<int>(sites.maximum);
    // In doubles: a small edge length on a large model gives more sites than an int holds.
    const double n = area / (std::sqrt(3.0) / 2.0 * edgeLength * edgeLength);
    if (!(n <= most))
        throw InputError("remesh: an edge length of " + number(edgeLength) + " gives about "
                         + number(n) + " sites, more than the " + std::to_string(most)
                         + " allowed; use an edge length of at least "
                         + number(edgeLengthForSites(area, most)));
    return std::max(static_cast<int>(sites.minimum), static_cast<int>(std::lround(n)));
}

double modelArea(const Model &model)
{
    double area = 0.0;
    for (const Surface &s : model.surfaces)
        area += surfaceArea(s);
    return area;
}

double edgeLengthForSites(double area, int sites)
{
    return sites > 0 && area > 0.0 ? std::sqrt(area / (std::sqrt(3.0) / 2.0 * sites)) : 0.0;
}

RemeshResult remeshWithSites(const Model &inputModel, const std::vector<Vec3> &sites,
                             const RemeshParams &params, Progress &progress)
{
    const Model input = withTopology(inputModel);
    SimplificationLedger ledger;
    const StripCollapse collapsed =
        stripsRemoved(input, edgeLengthForSites(modelArea(input), static_cast<int>(sites.size())),
                      params, ledger, progress);
    const std::size_t stripRecords = ledger.size();
    RemeshResult result = meshFromSites(collapsed, sites, params, std::move(ledger), progress);
    // Opening pockets changes the output, so the ledger is reconciled with the opened model.
    checkAndOpenPockets(result, Progress::none());
    result.cleanup.lineFins += mendFlatTriangles(result.model, result.validity).mended;
    reconcileLedger(input, result.model, result.ledger,
                    2.0 * edgeLengthForSites(modelArea(input), result.siteCount), stripRecords);
    return result;
}

namespace {

// One remesh; `restartWhenCapped` lets a search that the site cap stops on an invalid result
// start again from its best (below), which the rerun with the thin strips kept does not do.
RemeshResult remeshRun(const Model &inputModel, const RemeshParams &params, Progress &progress,
                       bool restartWhenCapped)
{
    const auto start = std::chrono::steady_clock::now();
    const Model input = withTopology(inputModel);
    checkParams(remeshParamTable(), params); // plain ranges; those that depend on the model below
    const ParamInfo &sitesRange = remeshParamTable().info("sites");
    const int most = static_cast<int>(sitesRange.maximum);
    const double area = modelArea(input);
    const int n = params.sites > 0 ? params.sites : sitesForEdgeLength(area, params.edgeLength);
    // Fewer sites than surfaces cannot give every surface a cell: the result would lose most of
    // the model (modelA5 at 4 sites: 12 regions on 9 surfaces).
    const int fewest =
        std::max(static_cast<int>(sitesRange.minimum), static_cast<int>(input.surfaces.size()));
    if (n < fewest || n > most)
        throw InputError(
            "remesh: " + std::to_string(n) + " sites is outside " + std::to_string(fewest) + ".."
            + std::to_string(most) + " for this model of " + std::to_string(input.surfaces.size())
            + " surfaces (edge length at most " + number(edgeLengthForSites(area, fewest)) + ")");
    const double diagonal = boundingBoxDiagonal(input.vertices);
    if (params.dResolution > kMaxDResolutionFraction * diagonal)
        throw InputError(
            "remesh: d_resolution " + number(params.dResolution)
            + " would merge features across a tenth of the model (bounding-box diagonal "
            + number(diagonal) + "); use at most " + number(kMaxDResolutionFraction * diagonal));
    // The run's share of the bar: strips, CVT, mesh building, validity, then refinement rounds
    // in the rest (each round half of what is left, so the bar never reaches its end early).
    SimplificationLedger ledger;
    StripCollapse collapsed;
    {
        Progress strips(progress, 0.0, 0.03, "Thin strips");
        collapsed = stripsRemoved(input, edgeLengthForSites(area, n), params, ledger, strips);
    }
    const Model &simplified = collapsed.model;
    const double h0 = edgeLengthForSites(area, n);
    std::vector<double> startDensity =
        params.adaptive ? adaptiveDensity(simplified, params) : std::vector<double>{};
    int sized = n;
    double smallest = h0;
    if (params.lfsFactor > 0.0) {
        Progress sizingProgress(progress, 0.03, 0.06, "Feature sizing");
        const FeatureSizing sizing = fittedSizing(simplified, h0, params, sizingProgress);
        sized = std::min(most, static_cast<int>(std::lround(n * sizing.siteFactor)));
        smallest = *std::min_element(sizing.size.begin(), sizing.size.end());
        const std::vector<double> rho = sizingDensity(sizing, h0);
        if (startDensity.empty())
            startDensity = rho;
        else
            for (std::size_t v = 0; v < rho.size(); ++v)
                startDensity[v] *= rho[v];
    }
    const RestrictionDomain domain = makeRestrictionDomain(simplified, startDensity);
    CvtParams cvt;
    cvt.iterations = params.iterations;
    cvt.alpha = params.boundaryWeight;
    Progress cvtProgress(progress, 0.06, 0.55, "CVT");
    const CvtResult optimised =
        params.iterations > 0
            ? optimizeCvt(domain, sampleSurfaces(domain, sized, params.seed), cvt, cvtProgress)
            : CvtResult{};
    std::vector<Vec3> sites =
        params.iterations > 0 ? optimised.sites : sampleSurfaces(domain, sized, params.seed);
    const double sampling = secondsSince(start);
    const std::size_t stripRecords = ledger.size();
    RemeshResult result;
    {
        Progress building(progress, 0.55, 0.8, "Mesh building");
        result = meshFromSites(collapsed, sites, params, ledger, building);
    }
    {
        Progress validity(progress, 0.8, 0.85, "Validity");
        checkAndOpenPockets(result, validity);
    }
    double at = 0.85; // where the next refinement round starts on this run's bar

    // Rounds of local refinement where the output is wrong (topology_refinement.h).
    std::vector<double> density = domain.density;
    int rounds = 0;
    auto score = [](const RemeshResult &r) {
        return std::make_pair(r.validity.problems.size(), countTopologyEdits(r.ledger).total());
    };
    result.refinementRounds = 0;
    RemeshResult best = result;
    const double baseSlivers = computeMeshStatistics(result.model).pctTrianglesAngleBelow30;
    auto withinAllowance = [&](const Model &m) {
        return computeMeshStatistics(m).pctTrianglesAngleBelow30
               <= baseSlivers + params.refinementMaxQualityLoss;
    };
    // Sites pinned on the features near wrong places (featureSitesNearTargets), and the split
    // model with the size field they follow, made again each round for all places so far.
    const bool pinFeatures = pinsFeatures(params);
    std::vector<char> pinned(sites.size(), 0);
    std::vector<Vec3> allTargets;
    SizedModel sized_;
    std::vector<double> fineDensity;
    StripCollapse fineCollapse;
    // When the site cap stops the search on an invalid best, it may start again from the best's
    // sites and density and refine only where that best is not valid: the places of a later
    // round, topology ones included, had used the sites up (a 10-fault network at 1000 sites
    // ended with 1 problem and 934 edits; started again, valid with 586 edits).
    std::vector<double> bestDensity = density;
    // Refines until no place is left, the rounds run out, no site can be added, or a round over
    // the quality allowance follows a valid best; a round is kept only when better than the best.
    // True when the site cap stopped it on an invalid best, the case a new start from that best
    // may mend.
    auto refine = [&](bool validityOnly) {
        for (;;) {
            const double spacing = edgeLengthForSites(area, static_cast<int>(sites.size()))
                                   * std::sqrt(sized / double(n));
            // Validity comes first: its places are refined while rounds are left, whatever the
            // growth cap; topology places only while the cap leaves room.
            const ValidityReport none;
            const std::vector<Vec3> topology =
                refinementTargets(simplified, result.model, result.ledger, stripRecords, none,
                                  mergeDistance(params), 0.5 * spacing);
            std::vector<Vec3> invalid;
            for (const ValidityProblem &p : result.validity.problems)
                invalid.push_back(p.position);
            result.remainingTargets = static_cast<int>(topology.size() + invalid.size());
            if (result.remainingTargets == 0 || params.refinementRounds == 0
                || rounds >= params.refinementRounds + (invalid.empty() ? 0 : 4))
                break;
            // Pinning the features may take the sites up to sizingMaxGrowth times those asked.
            const int room = pinFeatures
                                 ? static_cast<int>(std::lround(params.sizingMaxGrowth * n))
                                       - static_cast<int>(sites.size())
                                 : static_cast<int>(std::lround(params.refinementMaxGrowth * n))
                                       - (static_cast<int>(sites.size()) - sized);
            std::vector<Vec3> targets = invalid;
            if (room > 0 && rounds < params.refinementRounds && !validityOnly)
                targets.insert(targets.end(), topology.begin(), topology.end());
            if (targets.empty())
                break;
            const double radius = 1.5 * spacing;
            std::vector<Vec3> pins, graded;
            const double pinRadius = 0.6 * spacing; // about the cell of the place
            if (pinFeatures) {
                // The model is split finer than the feature size around every place so far (so
                // that the domain carries the size field), pins go on its features near this
                // round's places and graded free sites around them.
                allTargets.insert(allTargets.end(), targets.begin(), targets.end());
                FeatureSizingParams sp;
                sp.edgeLength = h0;
                sp.lfsFactor = 1.0;
                sp.gradation = params.sizingGradation;
                sp.minEdgeLength = h0 / 64.0;
                sp.dResolution = mergeDistance(params);
                sized_ = refineToSize(simplified, sp, allTargets, radius, 6);
                const double coarse = 0.9 * spacing;
                for (const Vec3 &p : featureSitesNearTargets(sized_.model, sized_.size, targets,
                                                             pinRadius, coarse)) {
                    bool known = false;
                    for (std::size_t i = 0; i < sites.size() && !known; ++i)
                        known = pinned[i] && (sites[i] - p).squaredNorm() <= 1e-12 * h0 * h0;
                    if (!known)
                        pins.push_back(p);
                }
                fineDensity.clear();
                if (!pins.empty()) {
                    std::vector<double> base = density;
                    if (base.empty())
                        base.assign(simplified.vertices.size(), 1.0);
                    fineDensity = extendToAdded(sized_, base);
                    const RestrictionDomain fine = makeRestrictionDomain(sized_.model);
                    graded =
                        gradedSitesNearTargets(fine, sized_.size, targets, radius, coarse,
                                               params.seed + 104729u * (rounds + 1), fineDensity);
                }
            }
            raiseDensity(domain, targets, radius, params.refinementDensityFactor, density);
            const int near = std::max(4, sitesNearTargets(sites, targets, radius));
            int extra =
                static_cast<int>(std::lround((params.refinementDensityFactor - 1.0) * near));
            // Topology places share the growth cap; places that are not valid get at most as many
            // sites again (an 8-fault network doubled its sites every round to 15 GB without it).
            extra = std::min(extra, std::max(room, 0) + (invalid.empty() ? 0 : n));
            extra = std::min(extra, sized + 2 * n - static_cast<int>(sites.size()));
            if (pinFeatures) {
                extra = std::min(extra, std::max(room, 0));
                const int left = std::max(0, room - extra - static_cast<int>(pins.size()));
                if (static_cast<int>(graded.size()) > left)
                    graded.resize(left); // random order: a uniform thinning
            }
            if (extra <= 0 && pins.empty())
                return !validityOnly && !pinFeatures && !best.validity.problems.empty();
            const std::vector<Vec3> added = sampleNearTargets(
                domain, targets, radius, std::max(extra, 0), params.seed + 7919u * (rounds + 1));
            if (added.empty() && pins.empty())
                break;
            sites.insert(sites.end(), added.begin(), added.end());
            sites.insert(sites.end(), graded.begin(), graded.end());
            sites.insert(sites.end(), pins.begin(), pins.end());
            pinned.resize(sites.size() - pins.size(), 0);
            pinned.resize(sites.size(), 1);
            ++rounds;
            Progress round(progress, at, at + 0.5 * (1.0 - at),
                           "Refinement round " + std::to_string(rounds)
                               + (validityOnly ? " on invalid places" : ""));
            at += 0.5 * (1.0 - at);
            ProgressSteps roundSteps(round, {4, 5, 1});
            const bool fine = !fineDensity.empty();
            if (fine) {
                fineCollapse = collapsed;
                fineCollapse.model = sized_.model;
            }
            RestrictionDomain refined =
                fine ? makeRestrictionDomain(sized_.model, fineDensity) : domain;
            if (!fine)
                refined.density = density;
            CvtParams local = cvt;
            local.iterations = params.refinementIterations;
            local.fixedSites = pinned;
            if (fine) {
                // Graded random sites need many more iterations than a few added ones, and Lloyd
                // spaces them where L-BFGS, facing densities 64⁴ times apart, leaves them random
                // (modelA5 at 5000 sites: 5.1 % of triangles under 30° instead of 6.8 %, in 0.7
                // times the time).
                local.lloyd = true;
                local.alpha = 0.0;
                local.iterations *= 5;
            }
            if (local.iterations > 0) {
                Progress step = roundSteps.step(0, "CVT");
                std::vector<Vec3> moved = optimizeCvt(refined, sites, local, step).sites;
                for (std::size_t i = 0; i < sites.size(); ++i)
                    if (!pinned[i]) // a pinned site whose cell emptied may have been relocated
                        sites[i] = moved[i];
            }
            RemeshResult again;
            {
                Progress step = roundSteps.step(1, "Mesh building");
                again = meshFromSites(fine ? fineCollapse : collapsed, sites, params, ledger, step);
            }
            bool keepsQuality = withinAllowance(again.model);
            // A round over the quality allowance is kept only when it mends validity, and a valid
            // best leaves nothing to mend; the rounds after it add sites and go further over
            // (below). So the search stops before checking it (bench, modelA5 at 5000 sites: 5.11 s
            // instead of 5.37).
            if (!keepsQuality && !pinFeatures && best.validity.problems.empty())
                break;
            {
                Progress step = roundSteps.step(2, "Validity");
                checkAndOpenPockets(again, step);
            }
            // Opened pockets change triangles, so the round is judged on what it would keep.
            if (again.pocketsOpened > 0)
                keepsQuality = withinAllowance(again.model);
            // A round is kept only when it improves (validity first, then topology edits): the next
            // round still starts from its sites, but the result never gets worse by refining.
            const bool fixesValidity =
                again.validity.problems.size() < best.validity.problems.size();
            const bool improved =
                score(again) < score(best) && (fixesValidity || keepsQuality || pinFeatures);
            if (improved) {
                best = again;
                bestDensity = density;
                best.siteCount = static_cast<int>(sites.size());
                best.refinementRounds = rounds;
            }
            // Rounds only add sites: once one is valid and over the quality allowance, the next
            // ones go further over it and are not kept either (modelA5 at 5000 sites: rounds 3 and
            // 4 at 1.9 and 2.7 % of triangles under 30°, against 1.8 % allowed, cost 2.4 of 7.5 s).
            const bool overAllowance =
                again.validity.problems.empty() && !keepsQuality && !pinFeatures;
            result = std::move(again);
            if (overAllowance)
                break;
        }
        return false;
    };
    const bool cappedInvalid = refine(false);
    // Whole-strip removal moves lines before the remesh; when refinement cannot make its
    // result valid, the strips are kept and the run done again (their slivers beat an invalid
    // model). It comes before starting again from the best, which takes more edits (a 6-fault
    // network at 1000 sites: valid with 230 edits with its strips, with 482 started again).
    std::optional<RemeshResult> stripsKept;
    if (!best.validity.valid && params.stripWidthFactor > 0.0 && !best.strips.empty()
        && params.refinementRounds > 0) {
        RemeshParams keepStrips = params;
        keepStrips.stripWidthFactor = 0.0;
        Progress rerun(progress, at, at + 0.5 * (1.0 - at), "Keeping the thin strips");
        at += 0.5 * (1.0 - at);
        RemeshResult again = remeshRun(input, keepStrips, rerun, false);
        again.timings.samplingSeconds += sampling;
        again.timings.meshSeconds += best.timings.meshSeconds;
        if (again.validity.valid) {
            again.timings.totalSeconds = secondsSince(start);
            return again;
        }
        if (again.validity.problems.size() < best.validity.problems.size())
            stripsKept = std::move(again);
    }
    if (cappedInvalid && restartWhenCapped) {
        sites = best.sites;
        density = bestDensity;
        pinned.assign(sites.size(), 0);
        result = best;
        refine(true);
    }
    result = std::move(best);
    {
        Progress flat(progress, at, at + 0.5 * (1.0 - at), "Flat triangles");
        result.cleanup.lineFins +=
            mendFlatTriangles(result.model, result.validity, 170.0, 16, flat).mended;
    }
    const int roundsRun = rounds;
    rounds = result.refinementRounds;
    result.remainingTargets =
        static_cast<int>(refinementTargets(simplified, result.model, result.ledger, stripRecords,
                                           result.validity, mergeDistance(params), 0.5 * h0)
                             .size());
    reconcileLedger(input, result.model, result.ledger, 2.0 * h0, stripRecords);
    result.energy = optimised.energy;
    result.initialSiteCount = n;
    result.sizedSiteCount = sized;
    result.smallestCellSize = smallest;
    result.refinementRounds = rounds;
    result.refinementRoundsRun = roundsRun;
    result.timings.samplingSeconds = sampling;
    result.timings.totalSeconds = secondsSince(start);
    if (stripsKept && stripsKept->validity.problems.size() < result.validity.problems.size()) {
        stripsKept->timings.totalSeconds = secondsSince(start);
        return std::move(*stripsKept);
    }
    return result;
}

} // namespace

RemeshResult remeshModel(const Model &inputModel, const RemeshParams &params, Progress &progress)
{
    return remeshRun(inputModel, params, progress, true);
}

double mergeDistance(const RemeshParams &params)
{
    return std::max(0.0, params.dResolution);
}

bool pinsFeatures(const RemeshParams &params)
{
    return params.refinementPinsFeatures || params.dResolution == 0.0;
}

double stripWidthLimit(const RemeshParams &params, double edgeLength)
{
    if (!(params.stripWidthFactor > 0.0 && edgeLength > 0.0))
        return 0.0;
    const double width = params.stripWidthFactor * edgeLength;
    return params.dResolution < 0.0 ? width : std::min(width, params.dResolution);
}

TopologyEdits countTopologyEdits(const SimplificationLedger &ledger)
{
    TopologyEdits e;
    for (const LedgerRecord &r : ledger)
        switch (r.kind) {
        case LedgerKind::SurfaceLost:
            ++e.surfacesLost;
            break;
        case LedgerKind::SurfaceCreated:
            ++e.surfacesCreated;
            break;
        case LedgerKind::LineLost:
            ++e.linesLost;
            break;
        case LedgerKind::LineCreated:
            ++e.linesCreated;
            break;
        case LedgerKind::CornerLost:
            ++e.cornersLost;
            break;
        case LedgerKind::SurfacePartLost:
            ++e.surfacePartsLost;
            break;
        case LedgerKind::SurfacePartCreated:
            ++e.surfacePartsCreated;
            break;
        case LedgerKind::CornerCreated:
            ++e.cornersCreated;
            break;
        default:
            break;
        }
    return e;
}

} // namespace stratamesh
