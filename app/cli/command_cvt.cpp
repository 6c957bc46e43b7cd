// stratamesh-cli cvt MODEL --sites N [--seed S] [PARAMETERS: cvtParamTable()] [--json]
//     [--sites-out FILE.xyz] [--neighbours delaunay|nearest] [--overwrite]
// Optimises N sites over all surfaces and lines of a model (thesis Alg. 4.1, §4.3) and reports
// the energy per iteration, the restricted Delaunay triangulation's quality and the timings.
#include "cli_output.h"
#include "command_args.h"
#include "cvt/cvt_optimizer.h"
#include "cvt/initial_sampling.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "model/topology.h"
#include "params/param_tables.h"
#include "quality/restricted_delaunay_quality.h"
#include "voronoi/restricted_voronoi.h"

#include <QElapsedTimer>
#include <QJsonArray>

#include <sys/resource.h>

#include <cstdio>
#include <iomanip>
#include <limits>

namespace stratamesh::cli {

namespace {

double peakRssMb()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

void writeXyz(std::ostream &s, const std::vector<Vec3> &sites)
{
    s << std::setprecision(17);
    for (const Vec3 &p : sites)
        s << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

QJsonArray numbers(const std::vector<double> &values)
{
    QJsonArray a;
    for (double v : values)
        a.append(v);
    return a;
}

} // namespace

int runCvt(CommandArgs &args)
{
    const bool json = args.flag(QStringLiteral("--json"));
    CvtParams params;
    args.params(cvtParamTable(), params);
    const bool lloyd = params.lloyd;
    const double alpha = params.alpha;
    const int sites = args.intOption(QStringLiteral("--sites"), 0, 1, kMaxRemeshSites);
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    const int seed =
        args.intOption(QStringLiteral("--seed"), 1, 0, std::numeric_limits<int>::max());
    const std::optional<QString> sitesOut = args.option(QStringLiteral("--sites-out"));
    const QString neighbours =
        args.option(QStringLiteral("--neighbours")).value_or(QStringLiteral("nearest"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();
    if (sites < 1)
        throw UsageError(QStringLiteral("--sites N is required (N ≥ 1)"));
    if (neighbours != QLatin1String("delaunay") && neighbours != QLatin1String("nearest"))
        throw UsageError(QStringLiteral("--neighbours takes delaunay or nearest"));
    const NeighbourSearch search = neighbours == QLatin1String("nearest")
                                       ? NeighbourSearch::NearestNeighbours
                                       : NeighbourSearch::Delaunay;
    if (lloyd && alpha > 0)
        throw UsageError(
            QStringLiteral("--lloyd minimises the CVT energy only: it cannot take --alpha"));

    // The sites file is planned before the work: a folder that cannot take it fails now.
    OutputPlan plan({path.toStdString()}, overwrite);
    if (sitesOut)
        plan.add(sitesOut->toStdString(), "sites file");

    QElapsedTimer timer;
    timer.start();
    const Model model = recoverTopology(readModel(path.toStdString()));
    const RestrictionDomain domain = makeRestrictionDomain(model);
    const std::vector<Vec3> initial =
        sampleSurfaces(domain, sites, static_cast<std::uint64_t>(seed));

    params.neighbourSearch = search;
    if (!json)
        params.onIteration = [](const CvtIterationReport &r) {
            std::fprintf(stderr, "iteration %d: F = %.9g, |grad F| = %.4g\n", r.iteration, r.energy,
                         r.gradientNorm);
        };
    const CvtResult result = optimizeCvt(domain, initial, params);
    const RestrictedVoronoiDiagram rvd =
        computeRestrictedVoronoi(domain, result.sites, Progress::none(), search);
    const RestrictedDelaunayQuality q = restrictedDelaunayQuality(restrictedDelaunay(domain, rvd));
    if (sitesOut)
        plan.writeText(sitesOut->toStdString(),
                       [&](std::ostream &o) { writeXyz(o, result.sites); });
    plan.commit();
    int emptyCells = 0;
    for (const RestrictedCell &c : rvd.cells)
        emptyCells += c.area == 0 && c.length == 0;
    const double total = static_cast<double>(timer.nsecsElapsed()) * 1e-9;

    if (json) {
        printJson(QJsonObject{
            {QStringLiteral("model"), path},
            {QStringLiteral("sites"), sites},
            {QStringLiteral("empty_cells"), emptyCells},
            {QStringLiteral("relocated_sites"), result.relocatedSites},
            {QStringLiteral("iterations"), result.iterations},
            {QStringLiteral("evaluations"), result.evaluations},
            {QStringLiteral("stop_reason"), QString::fromStdString(result.stopReason)},
            {QStringLiteral("alpha"), alpha},
            {QStringLiteral("method"), lloyd ? QStringLiteral("lloyd") : QStringLiteral("lbfgs")},
            {QStringLiteral("initial_energy"), result.initialEnergy},
            {QStringLiteral("energy"), numbers(result.energy)},
            {QStringLiteral("gradient_norm"), numbers(result.gradientNorm)},
            {QStringLiteral("rdt"),
             QJsonObject{{QStringLiteral("triangles"), q.triangles},
                         {QStringLiteral("mean_quality"), q.meanQuality},
                         {QStringLiteral("min_angle_deg"), q.minAngleDeg},
                         {QStringLiteral("pct_triangles_angle_below_30"), q.percentAngleBelow30}}},
            {QStringLiteral("timings"),
             QJsonObject{{QStringLiteral("total_s"), total},
                         {QStringLiteral("optimisation_s"), result.totalSeconds},
                         {QStringLiteral("rvd_s"), result.rvdSeconds},
                         {QStringLiteral("delaunay_s"), result.delaunaySeconds},
                         {QStringLiteral("neighbours"), neighbours},
                         {QStringLiteral("threads"), result.threads}}},
            {QStringLiteral("peak_rss_mb"), peakRssMb()},
        });
        return 0;
    }
    out() << "model        " << path << '\n'
          << "sites        " << sites << " (" << emptyCells << " empty cells)\n"
          << "iterations   " << result.iterations << " ("
          << QString::fromStdString(result.stopReason) << ", " << result.evaluations
          << " evaluations)\n"
          << "energy       " << result.initialEnergy << " -> "
          << (result.energy.empty() ? result.initialEnergy : result.energy.back()) << '\n'
          << "RDT          " << q.triangles << " triangles, mean Q " << q.meanQuality
          << ", min angle " << q.minAngleDeg << " deg, " << q.percentAngleBelow30
          << " % with an angle < 30 deg\n"
          << "time         " << total << " s (RVD " << result.rvdSeconds << " s, Delaunay "
          << result.delaunaySeconds << " s, " << result.threads << " threads), peak memory "
          << peakRssMb() << " MB\n";
    return 0;
}

} // namespace stratamesh::cli
