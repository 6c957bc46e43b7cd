#include "review_decisions.h"

#include <QJsonArray>

#include <algorithm>

namespace stratamesh {

void ReviewDecisions::setDecision(int record, const ReviewDecision &decision)
{
    if (decision.isEmpty())
        m_decisions.remove(record);
    else
        m_decisions.insert(record, decision);
}

int ReviewDecisions::reviewedCount() const
{
    return int(std::count_if(m_decisions.cbegin(), m_decisions.cend(), [](const ReviewDecision &d) {
        return d.verdict != ReviewVerdict::Open;
    }));
}

QJsonObject ReviewDecisions::toJson() const
{
    QList<int> records = m_decisions.keys();
    std::sort(records.begin(), records.end());
    QJsonArray array;
    for (int record : records) {
        const ReviewDecision &d = m_decisions[record];
        QJsonObject entry{{QStringLiteral("record"), record},
                          {QStringLiteral("verdict"), verdictKey(d.verdict)}};
        if (!d.note.isEmpty())
            entry.insert(QStringLiteral("note"), d.note);
        array.append(entry);
    }
    return {{QStringLiteral("records"), array}};
}

std::optional<ReviewDecisions> ReviewDecisions::fromJson(const QJsonObject &json, int recordCount,
                                                         QString *error)
{
    const auto fail = [error](const QString &why) -> std::optional<ReviewDecisions> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    ReviewDecisions decisions;
    const QJsonValue records = json.value(QStringLiteral("records"));
    if (!records.isUndefined() && !records.isArray())
        return fail(QStringLiteral("review: \"records\" is not an array"));
    for (const QJsonValue &value : records.toArray()) {
        const QJsonObject entry = value.toObject();
        const QJsonValue recordValue = entry.value(QStringLiteral("record"));
        const double number = recordValue.toDouble(-1.0);
        if (!recordValue.isDouble() || number < 0 || number >= recordCount
            || number != double(int(number)))
            return fail(QStringLiteral("review: record %1 is not one of the ledger's %2 records")
                            .arg(recordValue.toVariant().toString())
                            .arg(recordCount));
        const auto verdict = verdictFromKey(entry.value(QStringLiteral("verdict")).toString());
        if (!verdict)
            return fail(QStringLiteral("review: record %1 has an unknown verdict \"%2\"")
                            .arg(int(number))
                            .arg(entry.value(QStringLiteral("verdict")).toString()));
        decisions.setDecision(int(number),
                              {*verdict, entry.value(QStringLiteral("note")).toString()});
    }
    return decisions;
}

QString verdictKey(ReviewVerdict verdict)
{
    switch (verdict) {
    case ReviewVerdict::Accepted:
        return QStringLiteral("accepted");
    case ReviewVerdict::Flagged:
        return QStringLiteral("flagged");
    case ReviewVerdict::Open:
        break;
    }
    return QStringLiteral("open");
}

std::optional<ReviewVerdict> verdictFromKey(const QString &key)
{
    for (ReviewVerdict v : {ReviewVerdict::Open, ReviewVerdict::Accepted, ReviewVerdict::Flagged})
        if (verdictKey(v) == key)
            return v;
    return std::nullopt;
}

} // namespace stratamesh
