// stratamesh-cli info MODEL [--json]: what a model holds and whether it is valid — entity counts
// with and without the box (thesis Table 3.1), mesh statistics (Table 4.2 columns), region
// volumes and the validity report.
#include "cli_output.h"
#include "command_args.h"
#include "io/model_reader.h"
#include "io/ringmesh_reader.h"
#include "io/ringmesh_topology.h"
#include "json_report.h"
#include "model/model_counts.h"
#include "model/region_volume.h"
#include "model/topology.h"
#include "model/validity.h"
#include "quality/mesh_statistics.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

namespace stratamesh::cli {

namespace {

struct InfoReport {
    QString path;
    Model model;
    ModelCounts counts;
    MeshStatistics mesh;
    std::vector<double> volumes;
    ValidityReport validity;
    double readSeconds = 0.0;
    double topologySeconds = 0.0;
    double validitySeconds = 0.0;
};

double seconds(QElapsedTimer &timer)
{
    const double s = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    timer.restart();
    return s;
}

InfoReport buildReport(const QString &path)
{
    InfoReport r;
    r.path = path;
    QElapsedTimer timer;
    timer.start();
    Model read = readModel(path.toStdString());
    r.readSeconds = seconds(timer);
    r.model = recoverTopology(std::move(read));
    r.topologySeconds = seconds(timer);
    r.counts = countEntities(r.model);
    r.mesh = computeMeshStatistics(r.model);
    r.volumes = regionVolumes(r.model);
    timer.restart();
    r.validity = checkValidity(r.model);
    if (isRingMeshFile(path.toStdString())) // a GeoModel also states its lines and corners
        addRingMeshTopologyProblems(path.toStdString(), r.model, r.validity);
    r.validitySeconds = seconds(timer);
    return r;
}

QJsonObject reportJson(const InfoReport &r)
{
    QJsonArray regions;
    for (std::size_t i = 0; i < r.model.regions.size(); ++i) {
        regions.append(QJsonObject{
            {QStringLiteral("name"), QString::fromStdString(r.model.regions[i].name)},
            {QStringLiteral("volume"), i < r.volumes.size() ? r.volumes[i] : 0.0},
        });
    }
    return QJsonObject{
        {QStringLiteral("file"), r.path},
        {QStringLiteral("name"), QString::fromStdString(r.model.name)},
        {QStringLiteral("counts"), toJson(r.counts)},
        {QStringLiteral("mesh"), toJson(r.mesh)},
        {QStringLiteral("histograms"),
         QJsonObject{{QStringLiteral("min_angle_deg"), toJson(minAngleHistogram(r.model))},
                     {QStringLiteral("quality"), toJson(qualityHistogram(r.model))}}},
        {QStringLiteral("regions"), regions},
        {QStringLiteral("validity"), toJson(r.validity)},
        {QStringLiteral("timings"), QJsonObject{{QStringLiteral("read_s"), r.readSeconds},
                                                {QStringLiteral("topology_s"), r.topologySeconds},
                                                {QStringLiteral("validity_s"), r.validitySeconds}}},
    };
}

QString number(double value, int precision = 4)
{
    return QString::number(value, 'g', precision);
}

void printText(const InfoReport &r)
{
    QTextStream &o = out();
    o << QFileInfo(r.path).fileName() << " — model \"" << QString::fromStdString(r.model.name)
      << "\"\n\n";
    o << QStringLiteral("%1 %2 %3\n")
             .arg(QString(), -10)
             .arg(QStringLiteral("all"), 8)
             .arg(QStringLiteral("without box"), 12);
    auto row = [&o](const char *name, int all, int withoutBox) {
        o << QStringLiteral("%1 %2 %3\n")
                 .arg(QLatin1String(name), -10)
                 .arg(all, 8)
                 .arg(withoutBox, 12);
    };
    row("regions", r.counts.all.regions, r.counts.withoutBox.regions);
    row("surfaces", r.counts.all.surfaces, r.counts.withoutBox.surfaces);
    row("lines", r.counts.all.lines, r.counts.withoutBox.lines);
    row("corners", r.counts.all.corners, r.counts.withoutBox.corners);

    const MeshStatistics &m = r.mesh;
    o << "\nmesh: " << groupedNumber(m.vertices) << " vertices, " << groupedNumber(m.triangles)
      << " triangles\n"
      << "  smallest angle " << number(m.minAngleDeg) << "°, "
      << QString::number(m.pctTrianglesAngleBelow30, 'f', 1)
      << " % of triangles with an angle < 30°, mean quality Q "
      << QString::number(m.meanQuality, 'f', 3) << '\n'
      << "  area " << number(m.area, 6) << ", bounding-box diagonal " << number(m.bboxDiagonal, 6)
      << '\n';

    o << "\nregions (volume):\n";
    for (std::size_t i = 0; i < r.model.regions.size(); ++i) {
        o << "  " << QString::fromStdString(r.model.regions[i].name).leftJustified(24) << ' '
          << number(i < r.volumes.size() ? r.volumes[i] : 0.0, 6) << '\n';
    }

    const ValidityReport &v = r.validity;
    if (v.valid) {
        o << "\nvalidity: valid\n";
    } else {
        std::size_t total = 0;
        for (const auto &entry : v.counts)
            total += entry.second;
        o << "\nvalidity: NOT valid, " << total << " problem(s)";
        for (const auto &[check, count] : v.counts)
            o << (check == v.counts.begin()->first ? ": " : ", ") << QString::fromStdString(check)
              << ' ' << count;
        o << '\n';
        for (const ValidityProblem &p : v.problems) {
            QStringList entities;
            for (const std::string &e : p.entities)
                entities << QString::fromStdString(e);
            o << "  [" << QString::fromStdString(p.check) << "] "
              << QString::fromStdString(p.message) << " (" << entities.join(QStringLiteral(", "))
              << ") at " << number(p.position.x(), 9) << ' ' << number(p.position.y(), 9) << ' '
              << number(p.position.z(), 9) << '\n';
        }
    }
    o << "\ntimings: read " << QString::number(r.readSeconds, 'f', 3) << " s, topology "
      << QString::number(r.topologySeconds, 'f', 3) << " s, validity "
      << QString::number(r.validitySeconds, 'f', 3) << " s\n";
}

} // namespace

int runInfo(CommandArgs &args)
{
    const bool json = args.flag(QStringLiteral("--json"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();

    const InfoReport report = buildReport(path);
    if (json)
        printJson(reportJson(report));
    else
        printText(report);
    return 0;
}

} // namespace stratamesh::cli
