#include "slurm_submission.h"

#include "common/error.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>

namespace stratamesh::study {

namespace {

QString slurmDir(const Study &study)
{
    return QDir(study.outputDir).filePath(QStringLiteral("slurm"));
}

QString quoted(const QString &text)
{
    QString q = text;
    q.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
    return QLatin1Char('\'') + q + QLatin1Char('\'');
}

void writeText(const QString &path, const QByteArray &bytes, bool executable)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) < 0 || !file.commit())
        throw FileError(path.toStdString(), 0, "cannot write: " + file.errorString().toStdString());
    if (executable)
        QFile::setPermissions(path, QFile::permissions(path) | QFileDevice::ExeOwner
                                        | QFileDevice::ExeGroup | QFileDevice::ExeOther);
}

QString sbatch(const QStringList &args)
{
    const QString program = QStandardPaths::findExecutable(QStringLiteral("sbatch"));
    if (program.isEmpty())
        throw InputError("sbatch not found: install the Slurm client (Debian slurm-client) and "
                         "point it at the cluster (SLURM_CONF or /etc/slurm/slurm.conf)");
    QProcess process;
    process.start(program, args);
    process.waitForFinished(120000);
    const QString out = QString::fromUtf8(process.readAllStandardOutput()).trimmed();
    if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0)
        throw InputError(
            "sbatch refused the job: "
            + QString::fromUtf8(process.readAllStandardError()).trimmed().toStdString());
    // --parsable prints "jobid[;cluster]".
    return out.section(QLatin1Char(';'), 0, 0);
}

QByteArray header(const Study &study, const SlurmOptions &options, const QString &name,
                  const QString &log)
{
    QByteArray h = "#!/bin/bash\n# Written by stratamesh-cli study --submit slurm for "
                   + study.path.toUtf8() + "\n";
    h += "#SBATCH --job-name=" + name.toUtf8() + "\n";
    h += "#SBATCH --output=" + log.toUtf8() + "\n";
    h += "#SBATCH --ntasks=1\n";
    if (!options.partition.isEmpty())
        h += "#SBATCH --partition=" + options.partition.toUtf8() + "\n";
    if (!options.time.isEmpty())
        h += "#SBATCH --time=" + options.time.toUtf8() + "\n";
    if (!options.memory.isEmpty())
        h += "#SBATCH --mem=" + options.memory.toUtf8() + "\n";
    return h;
}

} // namespace

QString arrayRanges(std::vector<int> ids)
{
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    QStringList parts;
    for (std::size_t i = 0; i < ids.size();) {
        std::size_t j = i;
        while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1)
            ++j;
        parts << (i == j ? QString::number(ids[i])
                         : QStringLiteral("%1-%2").arg(ids[i]).arg(ids[j]));
        i = j + 1;
    }
    return parts.join(QLatin1Char(','));
}

std::vector<int> arrayIdsOf(const QString &jobId)
{
    static const QRegularExpression single(QStringLiteral("^\\d+_(\\d+)$"));
    static const QRegularExpression ranges(QStringLiteral("^\\d+_\\[([0-9,\\-]+)(%\\d+)?\\]$"));
    std::vector<int> ids;
    if (const auto m = single.match(jobId); m.hasMatch()) {
        ids.push_back(m.captured(1).toInt());
        return ids;
    }
    const auto m = ranges.match(jobId);
    if (!m.hasMatch())
        return ids;
    for (const QString &part : m.captured(1).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const int a = part.section(QLatin1Char('-'), 0, 0).toInt();
        const int b =
            part.contains(QLatin1Char('-')) ? part.section(QLatin1Char('-'), 1, 1).toInt() : a;
        for (int id = a; id <= b && ids.size() < 1000000; ++id)
            ids.push_back(id);
    }
    return ids;
}

QJsonArray slurmSubmissions(const Study &study)
{
    QFile file(QDir(slurmDir(study)).filePath(QStringLiteral("submissions.json")));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).array();
}

SlurmSubmission submitToSlurm(const Study &study, const std::vector<int> &taskIds,
                              const SlurmOptions &options, const QString &cli)
{
    if (taskIds.empty())
        throw InputError("nothing to submit: every task of the study is done");
    const QDir dir(slurmDir(study));
    if (!QDir().mkpath(dir.path()))
        throw FileError(dir.path().toStdString(), 0, "cannot create the folder");
    const QJsonArray previous = slurmSubmissions(study);
    const QString n = QString::number(previous.size());

    QString array = arrayRanges(taskIds);
    if (options.maxParallel > 0)
        array += QStringLiteral("%") + QString::number(options.maxParallel);
    const QString arrayScript = dir.filePath(QStringLiteral("tasks-%1.sh").arg(n));
    QByteArray tasks = header(study, options, QStringLiteral("stratamesh-study"),
                              dir.filePath(QStringLiteral("task-%A_%a.log")));
    tasks += "exec " + quoted(cli).toUtf8() + " study " + quoted(study.path).toUtf8()
             + " --task \"$SLURM_ARRAY_TASK_ID\"\n";
    writeText(arrayScript, tasks, true);

    const QString gatherScript = dir.filePath(QStringLiteral("gather-%1.sh").arg(n));
    QByteArray gather = header(study, options, QStringLiteral("stratamesh-gather"),
                               dir.filePath(QStringLiteral("gather-%j.log")));
    gather +=
        "exec " + quoted(cli).toUtf8() + " study " + quoted(study.path).toUtf8() + " --gather\n";
    writeText(gatherScript, gather, true);

    SlurmSubmission s;
    s.taskIds = taskIds;
    s.arrayJob =
        sbatch({QStringLiteral("--parsable"), QStringLiteral("--array=") + array, arrayScript});
    s.gatherJob = sbatch({QStringLiteral("--parsable"),
                          QStringLiteral("--dependency=afterany:") + s.arrayJob, gatherScript});

    QJsonArray all = previous;
    QJsonArray ids;
    for (int id : taskIds)
        ids.append(id);
    all.append(QJsonObject{
        {QStringLiteral("array_job"), s.arrayJob},
        {QStringLiteral("gather_job"), s.gatherJob},
        {QStringLiteral("array"), array},
        {QStringLiteral("tasks"), ids},
        {QStringLiteral("submitted_at"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)}});
    writeText(dir.filePath(QStringLiteral("submissions.json")), QJsonDocument(all).toJson(), false);
    return s;
}

std::map<int, QString> queuedTasks(const Study &study, bool *squeueAvailable)
{
    std::map<int, QString> queued;
    const QString squeue = QStandardPaths::findExecutable(QStringLiteral("squeue"));
    if (squeueAvailable)
        *squeueAvailable = !squeue.isEmpty();
    const QJsonArray submissions = slurmSubmissions(study);
    if (squeue.isEmpty() || submissions.isEmpty())
        return queued;
    QStringList jobs;
    for (const QJsonValue &s : submissions)
        jobs << s.toObject().value(QStringLiteral("array_job")).toString();
    QProcess process;
    process.start(squeue, {QStringLiteral("-h"), QStringLiteral("-r"), QStringLiteral("-o"),
                           QStringLiteral("%i %T"), QStringLiteral("-j"), jobs.join(',')});
    process.waitForFinished(60000);
    if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        // squeue -j fails once every job has left the queue: nothing queued.
        return queued;
    }
    for (const QString &line : QString::fromUtf8(process.readAllStandardOutput())
                                   .split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QString id = line.section(QLatin1Char(' '), 0, 0);
        const QString state = line.section(QLatin1Char(' '), 1, 1);
        for (int task : arrayIdsOf(id))
            queued[task] = state;
    }
    return queued;
}

} // namespace stratamesh::study
