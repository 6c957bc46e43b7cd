#include "study_plan.h"

#include "common/error.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>

namespace stratamesh::study {

QString optionText(const QJsonValue &value)
{
    if (value.isBool())
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (value.isDouble())
        return QString::number(value.toDouble(), 'g', 17);
    return value.toString();
}

QStringList StudyTask::arguments(const QString &step) const
{
    QStringList args;
    for (const auto &[name, point] : options) {
        if (name != step)
            continue;
        for (const auto &[key, value] : point) {
            // A boolean axis is a flag: present for true, absent for false.
            if (value.isBool()) {
                if (value.toBool())
                    args << QStringLiteral("--") + key;
                continue;
            }
            args << QStringLiteral("--") + key << optionText(value);
        }
    }
    return args;
}

QJsonObject StudyTask::toJson() const
{
    QJsonObject parameters;
    for (const auto &[step, point] : options) {
        QJsonObject o;
        for (const auto &[key, value] : point)
            o.insert(key, value);
        parameters.insert(step, o);
    }
    return QJsonObject{{QStringLiteral("id"), id},
                       {QStringLiteral("model"), model},
                       {QStringLiteral("folder"), folder},
                       {QStringLiteral("parameters"), parameters}};
}

std::vector<StudyTask> planTasks(const Study &study)
{
    // Axes of every step, flattened: the last axis varies fastest.
    struct FlatAxis {
        QString step;
        const GridAxis *axis;
    };
    std::vector<FlatAxis> flat;
    qint64 points = 1;
    for (const QString &step : study.steps)
        for (const GridAxis &axis : study.axes(step)) {
            flat.push_back({step, &axis});
            points *= static_cast<qint64>(axis.values.size());
            if (points * study.models.size() > kMaxStudyTasks)
                throw FileError(study.path.toStdString(), 0,
                                "the grid gives more than " + std::to_string(kMaxStudyTasks)
                                    + " tasks; split the study");
        }

    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9._+-]"));
    std::vector<StudyTask> tasks;
    int id = 0;
    for (const QString &model : study.models) {
        for (qint64 p = 0; p < points; ++p) {
            StudyTask task;
            task.id = id++;
            task.model = model;
            for (const QString &step : study.steps)
                task.options.push_back({step, {}});
            QString name = QStringLiteral("%1-%2")
                               .arg(task.id, 4, 10, QLatin1Char('0'))
                               .arg(QFileInfo(model).completeBaseName());
            qint64 rest = p;
            std::vector<std::size_t> index(flat.size());
            for (std::size_t a = flat.size(); a-- > 0;) {
                const qint64 n = static_cast<qint64>(flat[a].axis->values.size());
                index[a] = static_cast<std::size_t>(rest % n);
                rest /= n;
            }
            for (std::size_t a = 0; a < flat.size(); ++a) {
                const QJsonValue &value = flat[a].axis->values[index[a]];
                for (auto &[step, point] : task.options)
                    if (step == flat[a].step)
                        point.emplace_back(flat[a].axis->key, value);
                if (flat[a].axis->values.size() > 1)
                    name += QStringLiteral("-") + flat[a].axis->key + optionText(value);
            }
            name.replace(unsafe, QStringLiteral("_"));
            task.folder = QDir(study.outputDir).filePath(name);
            tasks.push_back(std::move(task));
        }
    }
    return tasks;
}

} // namespace stratamesh::study
