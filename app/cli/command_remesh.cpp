// stratamesh-cli remesh MODEL (--sites N | --edge-length L) [--d-resolution D] [--iterations 100]
//     [--seed S] [--adaptive] [--merge-all] [--strip-factor F] [--allow-invalid] -o
//     OUT.(ml|ts|gm|msh|vtu|vtk|vtp) --report REPORT.json
// Remeshes every surface of a model at once at the chosen resolution (thesis ch. 4), writes the
// new model, and a JSON report: input and output (counts and mesh as `info --json`, validity),
// the Hausdorff distance, histograms, timings, the simplification ledger and the CVT energy.
#include "cli_output.h"
#include "command_args.h"
#include "common/error.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "json_report.h"
#include "model/model_counts.h"
#include "model/topology.h"
#include "model/validity.h"
#include "quality/model_comparison.h"
#include "remesh/ledger_reconciliation.h"
#include "remesh/remesh_review.h"
#include "remesh/surface_remesher.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>

namespace stratamesh::cli {

namespace {

QJsonArray vec3(const Vec3 &v)
{
    return QJsonArray{v.x(), v.y(), v.z()};
}

QJsonObject countsJson(const EntityCounts &c)
{
    return QJsonObject{{QStringLiteral("regions"), c.regions},
                       {QStringLiteral("surfaces"), c.surfaces},
                       {QStringLiteral("lines"), c.lines},
                       {QStringLiteral("corners"), c.corners}};
}

// Same keys as `info --json`.
QJsonObject validityJson(const ValidityReport &report)
{
    QJsonArray problems;
    for (const ValidityProblem &p : report.problems) {
        QJsonArray entities;
        for (const std::string &e : p.entities)
            entities.append(QString::fromStdString(e));
        problems.append(
            QJsonObject{{QStringLiteral("check"), QString::fromStdString(p.check)},
                        {QStringLiteral("entities"), entities},
                        {QStringLiteral("position"), vec3(p.position)},
                        {QStringLiteral("message"), QString::fromStdString(p.message)}});
    }
    QJsonObject counts;
    for (const auto &[check, count] : report.counts)
        counts.insert(QString::fromStdString(check), static_cast<qint64>(count));
    return QJsonObject{{QStringLiteral("valid"), report.valid},
                       {QStringLiteral("problems"), problems},
                       {QStringLiteral("counts"), counts}};
}

QJsonObject sideJson(const Model &model, const MeshStatistics &mesh, const ValidityReport &validity)
{
    const ModelCounts counts = countEntities(model);
    return QJsonObject{
        {QStringLiteral("counts"),
         QJsonObject{{QStringLiteral("all"), countsJson(counts.all)},
                     {QStringLiteral("without_box"), countsJson(counts.withoutBox)}}},
        {QStringLiteral("mesh"), toJson(mesh)},
        {QStringLiteral("validity"), validityJson(validity)}};
}

QJsonArray refsJson(const std::vector<EntityRef> &refs)
{
    QJsonArray a;
    for (const EntityRef &r : refs)
        a.append(
            QJsonObject{{QStringLiteral("kind"), QString::fromStdString(entityKindName(r.kind))},
                        {QStringLiteral("id"), r.id},
                        {QStringLiteral("name"), QString::fromStdString(r.name)}});
    return a;
}

QJsonArray ledgerJson(const SimplificationLedger &ledger)
{
    QJsonArray a;
    for (const LedgerRecord &r : ledger)
        a.append(
            QJsonObject{{QStringLiteral("kind"), QString::fromStdString(ledgerKindName(r.kind))},
                        {QStringLiteral("inputs"), refsJson(r.inputs)},
                        {QStringLiteral("outputs"), refsJson(r.outputs)},
                        {QStringLiteral("position"), vec3(r.position)},
                        {QStringLiteral("size"), r.size},
                        {QStringLiteral("size_meaning"), QString::fromStdString(r.sizeMeaning)},
                        {QStringLiteral("note"), QString::fromStdString(r.note)},
                        {QStringLiteral("cause"), r.cause}});
    return a;
}

QJsonObject balanceJson(const LedgerBalance &b)
{
    auto one = [](const EntityBalance &e) {
        return QJsonObject{{QStringLiteral("input"), e.input},
                           {QStringLiteral("lost"), e.lost},
                           {QStringLiteral("created"), e.created},
                           {QStringLiteral("output"), e.output},
                           {QStringLiteral("balanced"), e.balanced()}};
    };
    return QJsonObject{{QStringLiteral("surfaces"), one(b.surfaces)},
                       {QStringLiteral("lines"), one(b.lines)},
                       {QStringLiteral("corners"), one(b.corners)},
                       {QStringLiteral("balanced"), b.balanced()}};
}

void writeModelFile(const Model &model, const QString &path)
{
    exportModel(model, path.toStdString());
}

void writeReport(const QJsonObject &report, const QString &path)
{
    QSaveFile file(path); // written beside, renamed on commit
    if (!file.open(QIODevice::WriteOnly)
        || file.write(QJsonDocument(report).toJson(QJsonDocument::Indented)) < 0 || !file.commit())
        throw FileError(path.toStdString(), 0,
                        "cannot write the report: " + file.errorString().toStdString());
}

} // namespace

int runRemesh(CommandArgs &args)
{
    RemeshParams params;
    params.sites = args.intOption(QStringLiteral("--sites"), 0, 4, 10000000);
    params.edgeLength = args.doubleOption(QStringLiteral("--edge-length"), 0.0, 0.0, 1e300);
    params.dResolution = args.doubleOption(QStringLiteral("--d-resolution"), 0.0, 0.0, 1e300);
    params.iterations = args.intOption(QStringLiteral("--iterations"), 100, 0, 100000);
    params.seed = static_cast<unsigned>(args.intOption(QStringLiteral("--seed"), 1, 0, 2147483647));
    params.adaptive = args.flag(QStringLiteral("--adaptive"));
    params.mergeAllExtraPoints = args.flag(QStringLiteral("--merge-all"));
    params.stripWidthFactor =
        args.doubleOption(QStringLiteral("--strip-factor"), params.stripWidthFactor, 0.0, 1.0);
    params.refinementRounds =
        args.intOption(QStringLiteral("--refinement-rounds"), params.refinementRounds, 0, 100);
    const bool allowInvalid = args.flag(QStringLiteral("--allow-invalid"));
    const std::optional<QString> output = args.option(QStringLiteral("-o"));
    const std::optional<QString> reportPath = args.option(QStringLiteral("--report"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();
    if ((params.sites > 0) == (params.edgeLength > 0.0))
        throw UsageError(QStringLiteral("give exactly one of --sites N and --edge-length L"));
    if (!output)
        throw UsageError(QStringLiteral("missing -o OUT.ml (or .ts, .gm, .msh, .vtu, .vtk, .vtp)"));
    const QString ext = QFileInfo(*output).suffix().toLower();
    static const QStringList modelFormats{
        QStringLiteral("ml"),  QStringLiteral("ts"),  QStringLiteral("gm"), QStringLiteral("msh"),
        QStringLiteral("vtu"), QStringLiteral("vtk"), QStringLiteral("vtp")};
    if (!modelFormats.contains(ext))
        throw UsageError(
            QStringLiteral(
                "the output must be a model file (.ml, .ts, .gm, .msh, .vtu, .vtk, .vtp), not '%1'")
                .arg(*output));
    // Refused before the run, not after it: overwriting the input, or a report nobody can write.
    if (QFileInfo(*output).absoluteFilePath() == QFileInfo(path).absoluteFilePath()
        || (QFileInfo::exists(*output)
            && QFileInfo(*output).canonicalFilePath() == QFileInfo(path).canonicalFilePath()))
        throw UsageError(
            QStringLiteral("the output '%1' is the input model; choose another file").arg(*output));
    for (const QString &target : {*output, reportPath.value_or(QString())}) {
        if (target.isEmpty())
            continue;
        const QFileInfo dir(QFileInfo(target).absolutePath());
        if (!dir.isDir() || !dir.isWritable())
            throw UsageError(
                QStringLiteral("cannot write '%1': its folder does not exist or is not writable")
                    .arg(target));
    }

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
    writeModelFile(result.model, *output);

    const ModelComparison &comparison = review.comparison;
    const ValidityReport &inValidity = review.inputValidity;
    const TopologyEdits edits = countTopologyEdits(result.ledger);
    QJsonArray energy;
    for (double e : result.energy)
        energy.append(e);
    const QJsonObject report{
        {QStringLiteral("file"), path},
        {QStringLiteral("output_file"), *output},
        {QStringLiteral("topology_edits"),
         QJsonObject{{QStringLiteral("total"), edits.total()},
                     {QStringLiteral("surfaces_lost"), edits.surfacesLost},
                     {QStringLiteral("surfaces_created"), edits.surfacesCreated},
                     {QStringLiteral("lines_lost"), edits.linesLost},
                     {QStringLiteral("lines_created"), edits.linesCreated},
                     {QStringLiteral("corners_lost"), edits.cornersLost},
                     {QStringLiteral("corners_created"), edits.cornersCreated},
                     {QStringLiteral("surface_parts_lost"), edits.surfacePartsLost},
                     {QStringLiteral("surface_parts_created"), edits.surfacePartsCreated}}},
        {QStringLiteral("ledger_balance"),
         balanceJson(ledgerBalance(input, result.model, result.ledger))},
        {QStringLiteral("refinement"),
         QJsonObject{{QStringLiteral("initial_sites"), result.initialSiteCount},
                     {QStringLiteral("final_sites"), result.siteCount},
                     {QStringLiteral("rounds"), result.refinementRounds},
                     {QStringLiteral("remaining_places"), result.remainingTargets}}},
        {QStringLiteral("parameters"),
         QJsonObject{{QStringLiteral("sites"), result.initialSiteCount},
                     {QStringLiteral("final_sites"), result.siteCount},
                     {QStringLiteral("strip_factor"), params.stripWidthFactor},
                     {QStringLiteral("merge_all"), params.mergeAllExtraPoints},
                     {QStringLiteral("refinement_rounds"), params.refinementRounds},
                     {QStringLiteral("edge_length"), params.edgeLength},
                     {QStringLiteral("d_resolution"), params.dResolution},
                     {QStringLiteral("iterations"), params.iterations},
                     {QStringLiteral("seed"), static_cast<qint64>(params.seed)},
                     {QStringLiteral("adaptive"), params.adaptive}}},
        {QStringLiteral("input"), sideJson(input, comparison.input.mesh, inValidity)},
        {QStringLiteral("output"), sideJson(result.model, comparison.output.mesh, outValidity)},
        {QStringLiteral("hausdorff_pct_bbox"), comparison.hausdorff.symmetricPctBbox},
        {QStringLiteral("hausdorff"),
         QJsonObject{{QStringLiteral("input_to_output"), comparison.hausdorff.aToB},
                     {QStringLiteral("output_to_input"), comparison.hausdorff.bToA},
                     {QStringLiteral("symmetric"), comparison.hausdorff.symmetric},
                     {QStringLiteral("bbox_diagonal"), comparison.hausdorff.bboxDiagonal}}},
        {QStringLiteral("histograms"),
         QJsonObject{{QStringLiteral("min_angle_deg"),
                      QJsonObject{{QStringLiteral("input"), toJson(comparison.inputMinAngle)},
                                  {QStringLiteral("output"), toJson(comparison.outputMinAngle)}}},
                     {QStringLiteral("quality"),
                      QJsonObject{{QStringLiteral("input"), toJson(comparison.inputQuality)},
                                  {QStringLiteral("output"), toJson(comparison.outputQuality)}}}}},
        {QStringLiteral("timings"),
         QJsonObject{{QStringLiteral("sampling_s"), result.timings.samplingSeconds},
                     {QStringLiteral("mesh_s"), result.timings.meshSeconds},
                     {QStringLiteral("total_s"), result.timings.totalSeconds}}},
        {QStringLiteral("ledger"), ledgerJson(result.ledger)},
        {QStringLiteral("energy"), energy},
    };
    if (reportPath)
        writeReport(report, *reportPath);

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
    return 0;
}

} // namespace stratamesh::cli
