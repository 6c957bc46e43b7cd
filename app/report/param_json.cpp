#include "param_json.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>

#include <limits>

namespace stratamesh {

QJsonObject readJsonObject(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw FileError(path.toStdString(), 0, "cannot read: " + file.errorString().toStdString());
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError)
        throw FileError(path.toStdString(), 0,
                        "not JSON at byte " + std::to_string(error.offset) + ": "
                            + error.errorString().toStdString());
    if (!document.isObject())
        throw FileError(path.toStdString(), 0, "not a JSON object");
    return document.object();
}

double paramJsonNumber(const ParamInfo &info, const QJsonValue &value)
{
    if (value.isDouble())
        return value.toDouble();
    if (value.isString() && info.type == ParamType::Seed) {
        bool ok = false;
        const qulonglong n = value.toString().toULongLong(&ok);
        if (ok)
            return static_cast<double>(n);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace stratamesh
