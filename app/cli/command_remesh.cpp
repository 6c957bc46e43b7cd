// stratamesh-cli remesh MODEL (--sites N | --edge-length L) [PARAMETERS] [--allow-invalid]
//     [--params REPORT.json] -o OUT.(ml|ts|gm|msh|vtu|vtk|vtp) --report REPORT.json [--overwrite]
// (the parameters: remeshParamTable(); --params takes them from a report, flags override them)
// Remeshes every surface of a model at once at the chosen resolution (thesis ch. 4), writes the
// new model, and a JSON report: input and output (counts and mesh as `info --json`, validity),
// the Hausdorff distance, histograms, timings, the simplification ledger and the CVT energy.
// Both outputs are planned before the run and written together, or neither (io/output_plan.h).
#include "cli_output.h"
#include "command_args.h"
#include "common/error.h"
#include "io/formats.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "json_report.h"
#include "model/model_counts.h"
#include "model/topology.h"
#include "model/validity.h"
#include "param_json.h"
#include "params/param_tables.h"
#include "quality/model_comparison.h"
#include "remesh/ledger_reconciliation.h"
#include "remesh/remesh_review.h"
#include "remesh/surface_remesher.h"
#include "remesh/topology_refinement.h"
#include "remesh_report.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>

namespace stratamesh::cli {

using RemeshTable = ParamTable<RemeshParams>;

int runRemesh(CommandArgs &args)
{
    const RemeshTable &table = remeshParamTable();
    RemeshParams params;
    // A report's parameters first, so that the flags given with it override them.
    if (const std::optional<QString> from = args.option(QStringLiteral("--params"))) {
        paramsFromJson(table, readJsonObject(*from), params, *from);
        if (params.edgeLength > 0.0) // its `sites` were derived from the edge length asked
            params.sites = 0;
    }
    const std::vector<std::string> given = args.params(table, params);
    auto isGiven = [&given](const char *key) {
        return std::find(given.begin(), given.end(), key) != given.end();
    };
    if (isGiven("sites") && !isGiven("edge_length"))
        params.edgeLength = 0.0;
    else if (isGiven("edge_length") && !isGiven("sites"))
        params.sites = 0;
    const bool allowInvalid = args.flag(QStringLiteral("--allow-invalid"));
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    const std::optional<QString> output = args.option(QStringLiteral("-o"));
    const std::optional<QString> reportPath = args.option(QStringLiteral("--report"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();
    if ((params.sites > 0) == (params.edgeLength > 0.0))
        throw UsageError(QStringLiteral("give exactly one of --sites N and --edge-length L"));
    if (!output)
        throw UsageError(QStringLiteral("missing -o OUT (%1)")
                             .arg(QString::fromStdString(extensionList(FormatUse::WriteModel))));
    if (!isFileFor(output->toStdString(), FormatUse::WriteModel))
        throw UsageError(
            QStringLiteral("the output must be a model file (%1), not '%2'")
                .arg(QString::fromStdString(extensionList(FormatUse::WriteModel)), *output));
    // Refused before the run, not after it: overwriting the input, or an output nobody can write.
    OutputPlan plan({path.toStdString()}, overwrite);
    plan.add(output->toStdString(), "model");
    if (reportPath)
        plan.add(reportPath->toStdString(), "report");

    const Model input = recoverTopology(readModel(path.toStdString()));
    const RemeshReview review = remeshAndReview(input, params);
    const RemeshResult &result = review.result;
    const ValidityReport &outValidity = result.validity;
    if (!outValidity.valid && !allowInvalid) {
        const ValidityProblem &p = outValidity.problems.front();
        std::string names;
        for (const std::string &e : p.entities)
            names += (names.empty() ? "" : ", ") + e;
        throw InputError(
            "remesh: the result is not valid after " + std::to_string(result.refinementRounds)
            + " refinement round(s) (" + std::to_string(result.siteCount)
            + " sites): " + std::to_string(outValidity.problems.size()) + " problem(s), first ["
            + p.check + "] " + names + " at " + std::to_string(p.position.x()) + " "
            + std::to_string(p.position.y()) + " " + std::to_string(p.position.z()) + ": "
            + p.message + "; nothing written (--allow-invalid writes it anyway)");
    }
    plan.write(output->toStdString(),
               [&](const std::string &temporary) { exportModel(result.model, temporary); });

    const ModelComparison &comparison = review.comparison;
    const TopologyEdits edits = countTopologyEdits(result.ledger);
    RemeshReportParts parts;
    parts.file = path;
    parts.outputFile = *output;
    parts.input = &input;
    parts.output = &result.model;
    parts.params = &params;
    parts.ledger = &result.ledger;
    parts.comparison = &comparison;
    parts.inputValidity = &review.inputValidity;
    parts.outputValidity = &outValidity;
    parts.facts = {result.initialSiteCount, result.siteCount,
                   result.refinementRounds, result.refinementRoundsRun,
                   result.remainingTargets, result.timings,
                   result.energy,           result.sizedSiteCount,
                   result.smallestCellSize, result.pocketsOpened};
    const QJsonObject report = remeshReportJson(parts);
    if (reportPath)
        plan.writeText(reportPath->toStdString(), [&](std::ostream &o) {
            o << QJsonDocument(report).toJson(QJsonDocument::Indented).toStdString();
        });
    plan.commit();

    QTextStream &o = out();
    o << "remeshed " << QFileInfo(path).fileName() << " with " << result.siteCount << " sites ("
      << result.initialSiteCount << " asked, " << result.refinementRounds
      << " refinement rounds) into " << *output << '\n'
      << "  output: " << comparison.output.mesh.vertices << " vertices, "
      << comparison.output.mesh.triangles << " triangles, mean Q "
      << QString::number(comparison.output.mesh.meanQuality, 'f', 3) << ", "
      << QString::number(comparison.output.mesh.pctTrianglesAngleBelow30, 'f', 2) << " % < 30°\n"
      << "  Hausdorff " << QString::number(comparison.hausdorff.symmetricPctBbox, 'f', 3)
      << " % of the bbox diagonal, " << result.ledger.size() << " ledger records, " << edits.total()
      << " topology edits, " << (outValidity.valid ? "valid" : "NOT valid") << '\n'
      << "  time: sampling " << QString::number(result.timings.samplingSeconds, 'f', 2)
      << " s, mesh " << QString::number(result.timings.meshSeconds, 'f', 2) << " s\n";
    if (edits.total() > 0) {
        // Name what changed, so that a run stopped by the refinement caps says which features
        // it simplified without opening the ledger.
        const std::vector<std::string> names = topologyEditEntities(result.ledger);
        QStringList shown;
        for (std::size_t i = 0; i < names.size() && i < 8; ++i)
            shown << QString::fromStdString(names[i]);
        o << "  topology changed";
        if (result.remainingTargets > 0)
            o << " where refinement stopped (" << result.refinementRounds << " of "
              << params.refinementRounds << " rounds, " << result.siteCount << " sites)";
        o << ", input entities involved: " << shown.join(QStringLiteral(", "));
        if (names.size() > 8)
            o << ", … (" << names.size() << " in all)";
        o << "; the ledger has a record for each\n";
    }
    return 0;
}

} // namespace stratamesh::cli
