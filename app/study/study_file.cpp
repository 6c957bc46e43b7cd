#include "study_file.h"

#include "common/error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace stratamesh::study {

namespace {

[[noreturn]] void fail(const QString &path, int line, const QString &cause)
{
    throw FileError(path.toStdString(), line, cause.toStdString());
}

int lineOfOffset(const QByteArray &bytes, int offset)
{
    return 1
           + static_cast<int>(std::count(
               bytes.begin(), bytes.begin() + std::min<qsizetype>(offset, bytes.size()), '\n'));
}

// Options a study sets itself for every task; a grid may not override them.
bool reservedOption(const QString &key)
{
    static const QStringList reserved{
        QStringLiteral("o"),          QStringLiteral("report"),    QStringLiteral("json"),
        QStringLiteral("params"),     QStringLiteral("sites-out"), QStringLiteral("cells-vtk"),
        QStringLiteral("poly"),       QStringLiteral("overwrite"), QStringLiteral("allow-invalid"),
        QStringLiteral("msh-version")};
    return reserved.contains(key);
}

QStringList expandModel(const QString &studyPath, const QDir &base, const QString &pattern)
{
    const QString absolute = QDir::cleanPath(base.absoluteFilePath(pattern));
    if (!pattern.contains(QLatin1Char('*')) && !pattern.contains(QLatin1Char('?'))
        && !pattern.contains(QLatin1Char('['))) {
        if (!QFileInfo(absolute).isFile())
            fail(studyPath, 0,
                 QStringLiteral("model '%1' not found (looked for %2)").arg(pattern, absolute));
        return {absolute};
    }
    const QFileInfo info(absolute);
    const QDir dir = info.dir();
    if (QString(dir.path()).contains(QLatin1Char('*')))
        fail(studyPath, 0,
             QStringLiteral("model pattern '%1': wildcards only in the file name").arg(pattern));
    QStringList found;
    for (const QFileInfo &f : dir.entryInfoList({info.fileName()}, QDir::Files, QDir::Name))
        found << f.absoluteFilePath();
    if (found.isEmpty())
        fail(studyPath, 0, QStringLiteral("model pattern '%1' matches no file").arg(pattern));
    return found;
}

} // namespace

const QStringList &knownSteps()
{
    static const QStringList steps{QStringLiteral("complexity"), QStringLiteral("remesh"),
                                   QStringLiteral("tetmesh")};
    return steps;
}

const std::vector<GridAxis> &Study::axes(const QString &step) const
{
    static const std::vector<GridAxis> none;
    for (const auto &[name, axes] : grid)
        if (name == step)
            return axes;
    return none;
}

Study readStudy(const QString &path, const OptionCheck &hasOption, const ValueCheck &checkValue)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        fail(path, 0, QStringLiteral("cannot open the study: %1").arg(file.errorString()));
    constexpr qint64 kMaxStudyBytes = 16 * 1024 * 1024;
    if (file.size() > kMaxStudyBytes)
        fail(path, 0, QStringLiteral("a study file over 16 MB is not a study file"));
    const QByteArray bytes = file.readAll();
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        fail(path, lineOfOffset(bytes, error.offset),
             QStringLiteral("not JSON: %1").arg(error.errorString()));
    if (!doc.isObject())
        fail(path, 1, QStringLiteral("a study is a JSON object"));
    const QJsonObject root = doc.object();

    static const QStringList keys{QStringLiteral("schema_version"), QStringLiteral("name"),
                                  QStringLiteral("models"),         QStringLiteral("steps"),
                                  QStringLiteral("grid"),           QStringLiteral("output")};
    for (const QString &key : root.keys())
        if (!keys.contains(key))
            fail(path, 0,
                 QStringLiteral("unknown key '%1' (a study has %2)").arg(key, keys.join(", ")));

    const QJsonValue version = root.value(QStringLiteral("schema_version"));
    if (!version.isDouble() || version.toDouble() != std::floor(version.toDouble())
        || version.toInt() < 1)
        fail(path, 0, QStringLiteral("schema_version must be a whole number from 1"));
    if (version.toInt() > kStudySchemaVersion)
        fail(path, 0,
             QStringLiteral("schema_version %1 was written by a newer StrataMesh; this one reads "
                            "up to %2")
                 .arg(version.toInt())
                 .arg(kStudySchemaVersion));

    const QFileInfo info(path);
    const QDir base = info.absoluteDir();
    Study study;
    study.path = info.absoluteFilePath();
    study.name = root.value(QStringLiteral("name")).toString(info.completeBaseName());

    const QJsonValue models = root.value(QStringLiteral("models"));
    if (!models.isArray() || models.toArray().isEmpty())
        fail(path, 0, QStringLiteral("'models' must be a non-empty list of paths or globs"));
    for (const QJsonValue &m : models.toArray()) {
        if (!m.isString() || m.toString().isEmpty())
            fail(path, 0, QStringLiteral("every entry of 'models' is a path or a glob"));
        for (const QString &model : expandModel(path, base, m.toString()))
            if (!study.models.contains(model))
                study.models << model;
    }

    const QJsonValue steps = root.value(QStringLiteral("steps"));
    if (!steps.isArray() || steps.toArray().isEmpty())
        fail(path, 0, QStringLiteral("'steps' must list some of: %1").arg(knownSteps().join(", ")));
    QStringList asked;
    for (const QJsonValue &s : steps.toArray()) {
        if (!knownSteps().contains(s.toString()))
            fail(path, 0,
                 QStringLiteral("unknown step '%1' (steps: %2)")
                     .arg(s.toString(), knownSteps().join(", ")));
        if (asked.contains(s.toString()))
            fail(path, 0, QStringLiteral("step '%1' is listed twice").arg(s.toString()));
        asked << s.toString();
    }
    for (const QString &step : knownSteps())
        if (asked.contains(step))
            study.steps << step;

    const QJsonValue grid = root.value(QStringLiteral("grid"));
    if (!grid.isUndefined() && !grid.isObject())
        fail(path, 0, QStringLiteral("'grid' maps a step to its options' values"));
    const QJsonObject gridObject = grid.toObject();
    static const QRegularExpression optionName(QStringLiteral("^[a-z][a-z0-9-]*$"));
    for (const QString &step : gridObject.keys()) {
        if (!study.steps.contains(step))
            fail(path, 0,
                 QStringLiteral("grid.%1: '%1' is not one of the study's steps").arg(step));
        if (!gridObject.value(step).isObject())
            fail(path, 0, QStringLiteral("grid.%1 maps options to lists of values").arg(step));
        const QJsonObject options = gridObject.value(step).toObject();
        std::vector<GridAxis> axes;
        for (const QString &key : options.keys()) {
            const QString where = QStringLiteral("grid.%1.%2").arg(step, key);
            if (!optionName.match(key).hasMatch())
                fail(path, 0,
                     where
                         + QStringLiteral(": an option name is lower-case, as the "
                                          "command line spells it without '--'"));
            if (reservedOption(key))
                fail(path, 0, where + QStringLiteral(": the study sets --%1 itself").arg(key));
            if (hasOption && !hasOption(step, QStringLiteral("--") + key))
                fail(path, 0,
                     where
                         + QStringLiteral(": stratamesh-cli %1 has no option --%2").arg(step, key));
            GridAxis axis{key, {}};
            const QJsonValue v = options.value(key);
            const QJsonArray values = v.isArray() ? v.toArray() : QJsonArray{v};
            if (values.isEmpty())
                fail(path, 0, where + QStringLiteral(": no value"));
            for (const QJsonValue &value : values) {
                if (!value.isDouble() && !value.isString() && !value.isBool())
                    fail(path, 0,
                         where
                             + QStringLiteral(": values are numbers, strings or "
                                              "true/false"));
                if (checkValue) {
                    if (const QString why = checkValue(step, QStringLiteral("--") + key, value);
                        !why.isEmpty())
                        fail(path, 0, where + QStringLiteral(": ") + why);
                }
                axis.values.push_back(value);
            }
            axes.push_back(std::move(axis));
        }
        study.grid.emplace_back(step, std::move(axes));
    }

    const QString output = root.value(QStringLiteral("output")).toString();
    if (output.isEmpty())
        fail(path, 0, QStringLiteral("'output' names the folder that receives the tasks"));
    study.outputDir = QDir::cleanPath(base.absoluteFilePath(output));
    return study;
}

} // namespace stratamesh::study
