// stratamesh-cli complexity MODEL [PARAMETERS] [--json] [--cells-vtk OUT.vtu] [--overwrite] (the
// parameters:
//                complexityParamTable()):
// the complexity measures of thesis chapter 3, box excluded — counts (Table 3.1), geometric
// complexity (Table 3.2), size variation coefficients (Table 3.3) and the statistics of the
// number of elements per cell of a volumetric CVT for each number of cells (Table 3.4).
// --cells-vtk writes the cells with their counts; with several numbers of cells, one file each,
// named OUT_<cells>.vtu, all planned before the work and written together (io/output_plan.h).
#include "cli_output.h"
#include "command_args.h"
#include "complexity/complexity_report.h"
#include "io/cells_vtu_writer.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "model/topology.h"
#include "param_json.h"
#include "params/param_tables.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

namespace stratamesh::cli {

namespace {

QString vtkPath(const QString &base, int cells, bool several)
{
    if (!several)
        return base;
    const QFileInfo info(base);
    const QString suffix = info.suffix().isEmpty() ? QStringLiteral("vtu") : info.suffix();
    return info.dir().filePath(
        QStringLiteral("%1_%2.%3").arg(info.completeBaseName()).arg(cells).arg(suffix));
}

QJsonObject measuresJson(const Model &model, const GeometricComplexity &g)
{
    QJsonArray elements;
    auto add = [&](const char *type, const std::vector<ElementMeasures> &all, auto nameOf) {
        for (const ElementMeasures &m : all)
            elements.append(QJsonObject{{"type", type},
                                        {"name", QString::fromStdString(nameOf(m.element))},
                                        {"size", m.size},
                                        {"shape", m.shape},
                                        {"thickness", m.thickness},
                                        {"angle", m.angle},
                                        {"sum", m.sum()}});
    };
    add("region", g.regions, [&](int i) { return model.regions[i].name; });
    add("surface", g.surfaces, [&](int i) { return model.surfaces[i].name; });
    add("line", g.lines, [&](int i) { return model.lines[i].name; });
    return QJsonObject{{"regions", g.regionsTotal},
                       {"surfaces", g.surfacesTotal},
                       {"lines", g.linesTotal},
                       {"total", g.total()},
                       {"elements", elements}};
}

QJsonObject reportJson(const QString &path, const Model &model, const ComplexityParams &params,
                       const ComplexityReport &r, const QJsonObject &timings)
{
    const EntityCounts &c = r.counts;
    QJsonArray local;
    for (const LocalComplexity &l : r.local) {
        const CountStatistics &s = l.statistics;
        local.append(QJsonObject{{"cells", static_cast<int>(l.counts.size())},
                                 {"q10", s.q10},
                                 {"q50", s.q50},
                                 {"q90", s.q90},
                                 {"max", s.max},
                                 {"mean", s.mean},
                                 {"var_coeff", s.varCoeff},
                                 {"outside_cells", l.outsideCells},
                                 {"lloyd_iterations", l.cvt.iterations}});
    }
    return QJsonObject{
        {"file", path},
        {"name", QString::fromStdString(model.name)},
        {"parameters", paramsToJson(complexityParamTable(), params)},
        {"global", QJsonObject{{"counts", QJsonObject{{"regions", c.regions},
                                                      {"surfaces", c.surfaces},
                                                      {"lines", c.lines},
                                                      {"corners", c.corners},
                                                      {"total", c.regions + c.surfaces + c.lines
                                                                    + c.corners}}},
                               {"geometric", measuresJson(model, r.geometric)},
                               {"variation", QJsonObject{{"regions", r.variation.regions},
                                                         {"surfaces", r.variation.surfaces},
                                                         {"lines", r.variation.lines},
                                                         {"total", r.variation.total}}}}},
        {"local", local},
        {"timings", timings},
    };
}

void printText(const QString &path, const ComplexityParams &params, const ComplexityReport &r,
               const QJsonObject &timings)
{
    QTextStream &o = out();
    const EntityCounts &c = r.counts;
    o << QFileInfo(path).fileName() << " — complexity (box excluded; thesis ch. 3)\n\n";
    o << "counts (Table 3.1): regions " << c.regions << ", surfaces " << c.surfaces << ", lines "
      << c.lines << ", corners " << c.corners << ", total "
      << c.regions + c.surfaces + c.lines + c.corners << "\n";
    auto f2 = [](double v) { return QString::number(v, 'f', 2); };
    o << "geometric C_t+C_f+C_e+C_a (Table 3.2, h " << params.geometric.h << ", alpha "
      << params.geometric.alphaDegrees << "°): regions " << f2(r.geometric.regionsTotal)
      << ", surfaces " << f2(r.geometric.surfacesTotal) << ", lines " << f2(r.geometric.linesTotal)
      << ", total " << f2(r.geometric.total()) << "\n";
    o << "size variation std/mean (Table 3.3): regions " << f2(r.variation.regions) << ", surfaces "
      << f2(r.variation.surfaces) << ", lines " << f2(r.variation.lines) << ", total "
      << f2(r.variation.total) << "\n\n";
    o << "elements per cell (Table 3.4):\n";
    o << QStringLiteral("%1 %2 %3 %4 %5 %6 %7\n")
             .arg(QStringLiteral("cells"), 8)
             .arg(QStringLiteral("Q10"), 5)
             .arg(QStringLiteral("Q50"), 5)
             .arg(QStringLiteral("Q90"), 5)
             .arg(QStringLiteral("max"), 5)
             .arg(QStringLiteral("mean"), 7)
             .arg(QStringLiteral("var"), 7);
    for (const LocalComplexity &l : r.local) {
        const CountStatistics &s = l.statistics;
        o << QStringLiteral("%1 %2 %3 %4 %5 %6 %7\n")
                 .arg(static_cast<int>(l.counts.size()), 8)
                 .arg(s.q10, 5)
                 .arg(s.q50, 5)
                 .arg(s.q90, 5)
                 .arg(s.max, 5)
                 .arg(s.mean, 7, 'f', 3)
                 .arg(s.varCoeff, 7, 'f', 3);
    }
    o << "\ntimings (s):";
    for (auto it = timings.begin(); it != timings.end(); ++it)
        o << ' ' << it.key().chopped(2) << ' ' << QString::number(it.value().toDouble(), 'f', 2);
    o << '\n';
}

} // namespace

int runComplexity(CommandArgs &args)
{
    const bool json = args.flag(QStringLiteral("--json"));
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    ComplexityParams params;
    args.params(complexityParamTable(), params);
    const std::optional<QString> vtk = args.option(QStringLiteral("--cells-vtk"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();
    // Every cells file (one per number of cells) is planned before the work.
    OutputPlan plan({path.toStdString()}, overwrite);
    std::vector<std::string> vtkPaths;
    if (vtk)
        for (int cells : params.cells) {
            vtkPaths.push_back(vtkPath(*vtk, cells, params.cells.size() > 1).toStdString());
            plan.add(vtkPaths.back(), "cells file");
        }

    QJsonObject timings;
    QElapsedTimer timer;
    timer.start();
    auto lap = [&](const QString &key) {
        timings.insert(key, static_cast<double>(timer.nsecsElapsed()) * 1e-9);
        timer.restart();
    };
    Model read = readModel(path.toStdString());
    lap(QStringLiteral("read_s"));
    const Model model = recoverTopology(std::move(read));
    lap(QStringLiteral("topology_s"));
    const ComplexityReport report = computeComplexity(model, params);
    for (const auto &[stage, seconds] : report.timings)
        timings.insert(QString::fromStdString(stage) + QStringLiteral("_s"), seconds);
    timer.restart();
    if (vtk) {
        // report.local holds one entry per params.cells, in the same order.
        for (std::size_t i = 0; i < report.local.size() && i < vtkPaths.size(); ++i)
            plan.write(vtkPaths[i], [&](const std::string &temporary) {
                writeLocalComplexityVtu(temporary, report.local[i]);
            });
        plan.commit();
        lap(QStringLiteral("export_s"));
    }
    if (json)
        printJson(reportJson(path, model, params, report, timings));
    else
        printText(path, params, report, timings);
    return 0;
}

} // namespace stratamesh::cli
