// A parameter table's values as the `parameters` block of a report, and back: a report read with
// paramsFromJson gives the parameters of the run it describes (stratamesh-cli remesh --params).
#pragma once

#include "common/error.h"
#include "params/param_table.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <cmath>

namespace stratamesh {

template <class P>
QJsonObject paramsToJson(const ParamTable<P> &table, const P &params)
{
    QJsonObject o;
    for (const Param<P> &p : table.params()) {
        const QString key = QString::fromStdString(p.info.jsonKey);
        switch (p.info.type) {
        case ParamType::Flag:
            o.insert(key, p.get(params) != 0.0);
            break;
        case ParamType::Int:
            o.insert(key, static_cast<qint64>(p.get(params)));
            break;
        case ParamType::Seed:
            if (p.info.jsonString)
                o.insert(key, QString::number(static_cast<qulonglong>(p.get(params))));
            else
                o.insert(key, static_cast<qint64>(p.get(params)));
            break;
        case ParamType::Real:
            o.insert(key, p.get(params));
            break;
        case ParamType::IntList: {
            QJsonArray a;
            for (double v : p.getList(params))
                a.append(static_cast<qint64>(v));
            o.insert(key, a);
            break;
        }
        }
    }
    return o;
}

// The JSON object in a file (a report); FileError when it cannot be read or is not one.
QJsonObject readJsonObject(const QString &path);

// A number of a `parameters` block (a string for the seeds written as strings); NaN when the
// value is not one.
double paramJsonNumber(const ParamInfo &info, const QJsonValue &value);

// Sets the parameters `json` holds (a report with a `parameters` block, or the block itself);
// the others keep their values. FileError naming `file` for a value of the wrong type or out of
// its range. Returns the keys read.
template <class P>
QStringList paramsFromJson(const ParamTable<P> &table, const QJsonObject &json, P &params,
                           const QString &file)
{
    const QJsonObject block = json.contains(QStringLiteral("parameters"))
                                  ? json.value(QStringLiteral("parameters")).toObject()
                                  : json;
    QStringList read;
    auto fail = [&](const ParamInfo &info, const std::string &why) {
        throw FileError(file.toStdString(), 0,
                        "parameters: " + info.jsonKey + " " + why + " (" + table.algorithm() + ")");
    };
    for (const Param<P> &p : table.params()) {
        const QString key = QString::fromStdString(p.info.jsonKey);
        if (!block.contains(key))
            continue;
        const QJsonValue value = block.value(key);
        if (p.info.type == ParamType::Flag) {
            if (!value.isBool())
                fail(p.info, "is not true or false");
            p.set(params, value.toBool() ? 1.0 : 0.0);
        } else if (p.info.type == ParamType::IntList) {
            if (!value.isArray())
                fail(p.info, "is not a list of numbers");
            std::vector<double> list;
            for (const QJsonValue &v : value.toArray()) {
                const double n = paramJsonNumber(p.info, v);
                if (const std::string why = paramValueError(p.info, n); !why.empty())
                    fail(p.info, why);
                list.push_back(n);
            }
            p.setList(params, list);
        } else {
            const double n = paramJsonNumber(p.info, value);
            if (std::isnan(n))
                fail(p.info, "is not a number");
            if (const std::string why = paramValueError(p.info, n); !why.empty())
                fail(p.info, why);
            p.set(params, n);
        }
        read << key;
    }
    return read;
}

} // namespace stratamesh
