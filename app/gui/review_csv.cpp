#include "review_csv.h"

#include "ledger_table_model.h"

#include "io/atomic_file.h"

#include <QLocale>
#include <QStringList>

namespace stratamesh {

namespace {

// The shortest text that reads back as the same double: a spreadsheet loses nothing.
QString number(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace

QString csvField(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"'))
        && !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QString reviewCsv(const SimplificationLedger &ledger, const ReviewDecisions &decisions)
{
    const QLatin1String eol("\r\n");
    QString csv =
        QStringLiteral("record,kind,inputs,outputs,x,y,z,size,size_meaning,verdict,note") + eol;
    for (std::size_t i = 0; i < ledger.size(); ++i) {
        const LedgerRecord &r = ledger[i];
        const ReviewDecision d = decisions.decision(int(i));
        const QStringList fields{QString::number(i),
                                 QString::fromStdString(ledgerKindName(r.kind)),
                                 LedgerTableModel::entitiesText(r.inputs),
                                 LedgerTableModel::entitiesText(r.outputs),
                                 number(r.position.x()),
                                 number(r.position.y()),
                                 number(r.position.z()),
                                 number(r.size),
                                 QString::fromStdString(r.sizeMeaning),
                                 verdictKey(d.verdict),
                                 d.note};
        QStringList quoted;
        for (const QString &field : fields)
            quoted << csvField(field);
        csv += quoted.join(QLatin1Char(',')) + eol;
    }
    return csv;
}

void writeReviewCsv(const QString &path, const SimplificationLedger &ledger,
                    const ReviewDecisions &decisions)
{
    AtomicFile file(path.toStdString());
    file.stream() << reviewCsv(ledger, decisions).toStdString();
    file.commit();
}

} // namespace stratamesh
