#include "remesh_report.h"

#include "json_report.h"
#include "model/model_counts.h"
#include "param_json.h"
#include "params/param_tables.h"
#include "remesh/ledger_reconciliation.h"

#include <QJsonArray>

namespace stratamesh {

namespace {

QJsonObject sideJson(const Model &model, const MeshStatistics &mesh, const ValidityReport *validity)
{
    QJsonObject side{{QStringLiteral("counts"), toJson(countEntities(model))},
                     {QStringLiteral("mesh"), toJson(mesh)}};
    if (validity)
        side.insert(QStringLiteral("validity"), toJson(*validity));
    return side;
}

} // namespace

QJsonObject remeshReportJson(const RemeshReportParts &parts)
{
    const Model &input = *parts.input;
    const Model &output = *parts.output;
    const SimplificationLedger &ledger = *parts.ledger;
    const ModelComparison &comparison = *parts.comparison;
    const RemeshReportFacts &facts = parts.facts;
    const TopologyEdits edits = countTopologyEdits(ledger);
    QJsonArray energy;
    for (double e : facts.energy)
        energy.append(e);
    // Every table parameter, so that `remesh --params REPORT.json` repeats the run; `sites` is
    // the number the run started from (derived from the edge length when that was asked).
    QJsonObject parameters = paramsToJson(remeshParamTable(), *parts.params);
    parameters.insert(QStringLiteral("sites"), facts.initialSiteCount);
    parameters.insert(QStringLiteral("final_sites"), facts.siteCount);
    // What d_resolution let the run simplify, in metres at its resolution edge length.
    const RemeshParams &params = *parts.params;
    const double edgeLength = edgeLengthForSites(modelArea(input), facts.initialSiteCount);
    const QJsonObject simplification{
        {QStringLiteral("d_resolution"), params.dResolution},
        {QStringLiteral("automatic"), params.dResolution < 0.0},
        {QStringLiteral("edge_length"), edgeLength},
        {QStringLiteral("merge_distance"), mergeDistance(params)},
        {QStringLiteral("strip_width_limit"), stripWidthLimit(params, edgeLength)},
        {QStringLiteral("pin_features"), pinsFeatures(params)}};
    return QJsonObject{
        {QStringLiteral("file"), parts.file},
        {QStringLiteral("output_file"), parts.outputFile},
        {QStringLiteral("topology_edits"), toJson(edits)},
        {QStringLiteral("ledger_balance"), toJson(ledgerBalance(input, output, ledger))},
        {QStringLiteral("refinement"),
         QJsonObject{{QStringLiteral("initial_sites"), facts.initialSiteCount},
                     {QStringLiteral("final_sites"), facts.siteCount},
                     {QStringLiteral("sized_sites"), facts.sizedSiteCount},
                     {QStringLiteral("smallest_size"), facts.smallestCellSize},
                     {QStringLiteral("rounds"), facts.refinementRounds},
                     {QStringLiteral("rounds_run"), facts.refinementRoundsRun},
                     {QStringLiteral("remaining_places"), facts.remainingTargets},
                     {QStringLiteral("pockets_opened"), facts.pocketsOpened}}},
        {QStringLiteral("parameters"), parameters},
        {QStringLiteral("simplification"), simplification},
        {QStringLiteral("input"), sideJson(input, comparison.input.mesh, parts.inputValidity)},
        {QStringLiteral("output"), sideJson(output, comparison.output.mesh, parts.outputValidity)},
        {QStringLiteral("hausdorff_pct_bbox"), comparison.hausdorff.symmetricPctBbox},
        {QStringLiteral("hausdorff"),
         QJsonObject{{QStringLiteral("input_to_output"), comparison.hausdorff.aToB},
                     {QStringLiteral("output_to_input"), comparison.hausdorff.bToA},
                     {QStringLiteral("symmetric"), comparison.hausdorff.symmetric},
                     {QStringLiteral("mean_input_to_output"), comparison.hausdorff.meanAToB},
                     {QStringLiteral("mean_output_to_input"), comparison.hausdorff.meanBToA},
                     {QStringLiteral("bbox_diagonal"), comparison.hausdorff.bboxDiagonal}}},
        {QStringLiteral("histograms"),
         QJsonObject{{QStringLiteral("min_angle_deg"),
                      QJsonObject{{QStringLiteral("input"), toJson(comparison.inputMinAngle)},
                                  {QStringLiteral("output"), toJson(comparison.outputMinAngle)}}},
                     {QStringLiteral("quality"),
                      QJsonObject{{QStringLiteral("input"), toJson(comparison.inputQuality)},
                                  {QStringLiteral("output"), toJson(comparison.outputQuality)}}}}},
        {QStringLiteral("timings"),
         QJsonObject{{QStringLiteral("sampling_s"), facts.timings.samplingSeconds},
                     {QStringLiteral("mesh_s"), facts.timings.meshSeconds},
                     {QStringLiteral("total_s"), facts.timings.totalSeconds}}},
        {QStringLiteral("ledger"), toJson(ledger)},
        {QStringLiteral("energy"), energy},
    };
}

} // namespace stratamesh
