// What the geologist decided about each record of a remesh's simplification ledger: accepted,
// flagged, or not reviewed yet, with a free note. Kept per run, saved in the project file.
#pragma once

#include <QHash>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace stratamesh {

enum class ReviewVerdict { Open, Accepted, Flagged };

struct ReviewDecision {
    ReviewVerdict verdict = ReviewVerdict::Open;
    QString note;

    bool isEmpty() const { return verdict == ReviewVerdict::Open && note.isEmpty(); }
    bool operator==(const ReviewDecision &other) const
    {
        return verdict == other.verdict && note == other.note;
    }
};

// Keyed by the record's index in the ledger; records without a decision are Open.
class ReviewDecisions {
public:
    ReviewDecision decision(int record) const { return m_decisions.value(record); }
    // An empty decision (Open, no note) removes the entry.
    void setDecision(int record, const ReviewDecision &decision);
    // Records accepted or flagged (a note alone does not count as reviewed).
    int reviewedCount() const;
    bool isEmpty() const { return m_decisions.isEmpty(); }
    void clear() { m_decisions.clear(); }
    const QHash<int, ReviewDecision> &all() const { return m_decisions; }

    // {"records": [{"record": 3, "verdict": "accepted", "note": "…"}, …]}, sorted by record.
    QJsonObject toJson() const;
    // Records at or above `recordCount` and unknown verdicts are errors: the decisions belong to
    // another ledger. Returns nullopt and sets `error` then.
    static std::optional<ReviewDecisions> fromJson(const QJsonObject &json, int recordCount,
                                                   QString *error);

    bool operator==(const ReviewDecisions &other) const { return m_decisions == other.m_decisions; }

private:
    QHash<int, ReviewDecision> m_decisions;
};

QString verdictKey(ReviewVerdict verdict); // "open", "accepted", "flagged"
std::optional<ReviewVerdict> verdictFromKey(const QString &key);

} // namespace stratamesh
