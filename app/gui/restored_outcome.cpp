#include "restored_outcome.h"

#include "json_report_read.h"
#include "model/model_counts.h"

#include <QJsonArray>

namespace stratamesh {

RemeshOutcome restoredOutcome(std::shared_ptr<const Model> input, const ProjectRun &run,
                              RunRead &read, const QString &reportPath)
{
    const QJsonObject &report = read.report;
    RemeshOutcome o;
    o.input = std::move(input);
    auto output = std::make_shared<const Model>(std::move(read.output));
    o.output = output;
    o.comparison = restoredComparison(*o.input, *output, report, reportPath);
    o.counts = countEntities(*output);
    o.params = run.params;
    const QJsonObject refinement = report.value(QLatin1String("refinement")).toObject();
    o.siteCount = refinement.value(QLatin1String("final_sites")).toInt();
    o.initialSiteCount = refinement.value(QLatin1String("initial_sites")).toInt();
    o.refinementRounds = refinement.value(QLatin1String("rounds")).toInt();
    o.refinementRoundsRun = refinement.value(QLatin1String("rounds_run")).toInt();
    o.remainingTargets = refinement.value(QLatin1String("remaining_places")).toInt();
    o.sizedSiteCount = refinement.value(QLatin1String("sized_sites")).toInt();
    o.smallestCellSize = refinement.value(QLatin1String("smallest_size")).toDouble();
    o.pocketsOpened = refinement.value(QLatin1String("pockets_opened")).toInt();
    o.validity = validityFromJson(report.value(QLatin1String("output"))
                                      .toObject()
                                      .value(QLatin1String("validity"))
                                      .toObject(),
                                  reportPath);
    const QJsonObject timings = report.value(QLatin1String("timings")).toObject();
    o.timings.samplingSeconds = timings.value(QLatin1String("sampling_s")).toDouble();
    o.timings.meshSeconds = timings.value(QLatin1String("mesh_s")).toDouble();
    o.timings.totalSeconds = timings.value(QLatin1String("total_s")).toDouble();
    o.milliseconds = qint64(o.timings.totalSeconds * 1000.0);
    for (const QJsonValue &e : report.value(QLatin1String("energy")).toArray())
        o.energy.push_back(e.toDouble());
    o.ledger = std::make_shared<const SimplificationLedger>(std::move(read.ledger));
    return o;
}

} // namespace stratamesh
