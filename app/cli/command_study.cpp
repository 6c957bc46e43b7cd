// stratamesh-cli study STUDY.smstudy (--plan | --run [--jobs N] | --task ID | --gather | --status
//     | --submit slurm [...] | --resubmit-failed [...])
// A study file lists models, a grid of options per step and the steps to chain; each
// (model, grid point) is a task with a stable number and its own folder (app/study).
#include "cli_output.h"
#include "command_args.h"
#include "command_params.h"
#include "commands.h"
#include "common/error.h"
#include "slurm_submission.h"
#include "study_file.h"
#include "study_gather.h"
#include "study_plan.h"
#include "study_runner.h"
#include "study_task.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>

namespace stratamesh::cli {

namespace {

using namespace stratamesh::study;

// A grid key must be an option the step's command really has: read from the registry's usage.
bool commandHasOption(const QString &step, const QString &flag)
{
    const Command *command = findCommand(step);
    if (!command)
        return false;
    const QRegularExpression word(QRegularExpression::escape(flag) + QStringLiteral("(?![a-z-])"));
    // The expanded usage: table options stand behind "{params}" in the registry line.
    return QString::fromStdString(commandArguments(*command)).contains(word);
}

// A grid value must lie in its option's range, so that a study fails at --plan, not in its tasks.
QString optionValueError(const QString &step, const QString &flag, const QJsonValue &value)
{
    const Command *command = findCommand(step);
    if (!command)
        return {};
    for (const ParamInfo &info : commandParams(*command)) {
        if (QString::fromStdString(info.flag) != flag)
            continue;
        if (info.type == ParamType::Flag)
            return value.isBool() ? QString()
                                  : QStringLiteral("%1 is on or off: true or false").arg(flag);
        std::vector<double> numbers;
        if (value.isDouble()) {
            numbers.push_back(value.toDouble());
        } else if (value.isString()) {
            // "1000" as the command line would take it; "100,1000" for a list.
            const QStringList parts = info.type == ParamType::IntList
                                          ? value.toString().split(QLatin1Char(','))
                                          : QStringList{value.toString()};
            for (const QString &part : parts) {
                bool ok = false;
                numbers.push_back(part.trimmed().toDouble(&ok));
                if (!ok)
                    return QStringLiteral("%1 takes a number, not '%2'")
                        .arg(flag, value.toString());
            }
        } else {
            return QStringLiteral("%1 takes a number, not true/false").arg(flag);
        }
        for (double v : numbers)
            if (const std::string why = paramValueError(info, v); !why.empty())
                return QString::fromStdString(why);
        return {};
    }
    return {}; // an option outside the tables (an output path, a switch): the command checks it
}

QString cliPath()
{
    return QCoreApplication::applicationFilePath();
}

QJsonObject statusJson(const Study &study, const std::vector<StudyTask> &tasks)
{
    bool squeue = false;
    const std::map<int, QString> queued = queuedTasks(study, &squeue);
    int ok = 0, failed = 0, pending = 0, inQueue = 0;
    QJsonArray rows;
    for (const StudyTask &task : tasks) {
        const TaskStatus s = readTaskStatus(task);
        QJsonObject row{{QStringLiteral("task"), task.id},
                        {QStringLiteral("status"), taskStateName(s.state)}};
        if (s.state == TaskState::Ok)
            ++ok;
        else if (s.state == TaskState::Failed) {
            ++failed;
            row.insert(QStringLiteral("error"), s.error);
        } else
            ++pending;
        if (const auto it = queued.find(task.id); it != queued.end()) {
            row.insert(QStringLiteral("slurm"), it->second);
            ++inQueue;
        }
        rows.append(row);
    }
    return QJsonObject{{QStringLiteral("study"), study.path},
                       {QStringLiteral("tasks"), static_cast<int>(tasks.size())},
                       {QStringLiteral("done"), ok},
                       {QStringLiteral("failed"), failed},
                       {QStringLiteral("pending"), pending},
                       {QStringLiteral("in_slurm_queue"), inQueue},
                       {QStringLiteral("squeue_available"), squeue},
                       {QStringLiteral("submissions"), slurmSubmissions(study).size()},
                       {QStringLiteral("task_states"), rows}};
}

} // namespace

int runStudy(CommandArgs &args)
{
    const bool plan = args.flag(QStringLiteral("--plan"));
    const bool run = args.flag(QStringLiteral("--run"));
    const bool gather = args.flag(QStringLiteral("--gather"));
    const bool status = args.flag(QStringLiteral("--status"));
    const bool resubmit = args.flag(QStringLiteral("--resubmit-failed"));
    const bool json = args.flag(QStringLiteral("--json"));
    const std::optional<QString> task = args.option(QStringLiteral("--task"));
    const std::optional<QString> submit = args.option(QStringLiteral("--submit"));
    const int jobs = args.intOption(QStringLiteral("--jobs"), 1, 1, 256);
    SlurmOptions slurm;
    slurm.partition = args.option(QStringLiteral("--partition")).value_or(QString());
    slurm.time = args.option(QStringLiteral("--time")).value_or(QString());
    slurm.memory = args.option(QStringLiteral("--mem")).value_or(QString());
    slurm.maxParallel = args.intOption(QStringLiteral("--max-parallel"), 0, 0, 100000);
    const QString path = args.positional(QStringLiteral("STUDY"));
    args.finish();

    const int actions = int(plan) + int(run) + int(gather) + int(status) + int(resubmit)
                        + int(task.has_value()) + int(submit.has_value());
    if (actions != 1)
        throw UsageError(QStringLiteral("give exactly one of --plan, --run, --task ID, --gather, "
                                        "--status, --submit slurm, --resubmit-failed"));
    if (submit && *submit != QLatin1String("slurm"))
        throw UsageError(QStringLiteral("--submit knows only 'slurm', not '%1'").arg(*submit));

    const Study study = readStudy(path, commandHasOption, optionValueError);
    const std::vector<StudyTask> tasks = planTasks(study);

    if (plan) {
        QJsonArray list;
        for (const StudyTask &t : tasks)
            list.append(t.toJson());
        printJson(QJsonObject{{QStringLiteral("study"), study.path},
                              {QStringLiteral("name"), study.name},
                              {QStringLiteral("steps"), QJsonArray::fromStringList(study.steps)},
                              {QStringLiteral("output"), study.outputDir},
                              {QStringLiteral("tasks"), list}});
        return 0;
    }
    if (task) {
        bool isNumber = false;
        const int id = task->toInt(&isNumber);
        if (!isNumber || id < 0 || id >= static_cast<int>(tasks.size()))
            throw UsageError(QStringLiteral("--task takes a number from 0 to %1, not '%2'")
                                 .arg(tasks.size() - 1)
                                 .arg(*task));
        const TaskStatus s = runTask(study, tasks[static_cast<std::size_t>(id)], cliPath());
        if (json)
            printJson(s.json);
        else
            out() << "task " << id << ' ' << taskStateName(s.state)
                  << (s.error.isEmpty() ? QString() : QStringLiteral(": ") + s.error) << '\n';
        return s.state == TaskState::Ok ? 0 : 1;
    }
    if (run) {
        const RunSummary summary = runStudyLocally(
            study, tasks, jobs, cliPath(), [json](const StudyTask &t, const TaskStatus &s) {
                if (!json) {
                    out() << "task " << t.id << ' ' << taskStateName(s.state)
                          << (s.error.isEmpty() ? QString() : QStringLiteral(": ") + s.error)
                          << '\n';
                    out().flush();
                }
            });
        const QStringList written = writeGathered(study, gatherStudy(study, tasks));
        if (json)
            printJson(QJsonObject{{QStringLiteral("skipped"), summary.skipped},
                                  {QStringLiteral("ok"), summary.ok},
                                  {QStringLiteral("failed"), summary.failed},
                                  {QStringLiteral("table"), written.first()}});
        else
            out() << "study " << study.name << ": " << summary.ok << " ok, " << summary.failed
                  << " failed, " << summary.skipped << " already done; table " << written.first()
                  << '\n';
        return summary.failed == 0 ? 0 : 1;
    }
    if (gather) {
        const GatheredStudy g = gatherStudy(study, tasks);
        const QStringList written = writeGathered(study, g);
        if (json)
            printJson(QJsonObject{{QStringLiteral("csv"), written[0]},
                                  {QStringLiteral("json"), written[1]},
                                  {QStringLiteral("rows"), g.rows.size()},
                                  {QStringLiteral("summary"), g.summary}});
        else
            out() << "gathered " << g.rows.size() << " tasks into " << written[0] << " and "
                  << written[1] << '\n';
        return 0;
    }
    if (status) {
        printJson(statusJson(study, tasks));
        return 0;
    }
    std::vector<int> selected;
    for (const StudyTask &t : tasks) {
        const TaskState state = readTaskStatus(t).state;
        if (resubmit ? state == TaskState::Failed : state != TaskState::Ok)
            selected.push_back(t.id);
    }
    if (resubmit && selected.empty())
        throw InputError("no failed task to resubmit");
    const SlurmSubmission s = submitToSlurm(study, selected, slurm, cliPath());
    QJsonArray ids;
    for (int id : s.taskIds)
        ids.append(id);
    printJson(QJsonObject{{QStringLiteral("array_job"), s.arrayJob},
                          {QStringLiteral("gather_job"), s.gatherJob},
                          {QStringLiteral("tasks"), ids}});
    return 0;
}

} // namespace stratamesh::cli
