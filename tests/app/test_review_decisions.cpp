// ReviewDecisions as the project file keeps them (JSON round trip, and fromJson refusing the
// decisions of another ledger), and the review's CSV (quoting, one row per record in order).
#include "review_csv.h"
#include "review_decisions.h"

#include "common/error.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

QJsonObject entries(const QJsonArray &records)
{
    return {{QStringLiteral("records"), records}};
}

QJsonObject entry(const QJsonValue &record, const QString &verdict)
{
    return {{QStringLiteral("record"), record}, {QStringLiteral("verdict"), verdict}};
}

SimplificationLedger threeRecords()
{
    SimplificationLedger ledger(3);
    ledger[0].kind = LedgerKind::CornerMerge;
    ledger[0].inputs = {{EntityKind::Corner, 1, "c1"}, {EntityKind::Corner, 2, "c2"}};
    ledger[0].position = Vec3(1.5, -2.0, 3.25);
    ledger[0].size = 12.5;
    ledger[0].sizeMeaning = "distance";
    ledger[1].kind = LedgerKind::SurfaceLost;
    ledger[1].inputs = {{EntityKind::Surface, 4, "H1"}};
    ledger[1].size = 0.25;
    ledger[1].sizeMeaning = "area";
    ledger[2].kind = LedgerKind::LineLost;
    return ledger;
}

} // namespace

class TestReviewDecisions : public QObject {
    Q_OBJECT
private slots:
    void jsonRoundTrip()
    {
        ReviewDecisions d;
        d.setDecision(7, {ReviewVerdict::Flagged, QStringLiteral("pinché, « voir » F2, \"x\"")});
        d.setDecision(0, {ReviewVerdict::Accepted, {}});
        d.setDecision(3, {ReviewVerdict::Open, QStringLiteral("a note alone")});
        QCOMPARE(d.reviewedCount(), 2);
        // Through text, as in the project file.
        const QJsonObject json =
            QJsonDocument::fromJson(QJsonDocument(d.toJson()).toJson()).object();
        const QJsonArray records = json.value(QStringLiteral("records")).toArray();
        QCOMPARE(records.size(), 3);
        QCOMPARE(records[0].toObject().value(QStringLiteral("record")).toInt(), 0); // sorted
        QCOMPARE(records[2].toObject().value(QStringLiteral("record")).toInt(), 7);
        QVERIFY(!records[0].toObject().contains(QStringLiteral("note")));
        QString error;
        const auto back = ReviewDecisions::fromJson(json, 8, &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(*back == d);
        QCOMPARE(back->decision(7).note, d.decision(7).note);
        QCOMPARE(back->decision(5).verdict, ReviewVerdict::Open);
        // Clearing a decision removes it.
        ReviewDecisions cleared = *back;
        cleared.setDecision(7, {});
        QCOMPARE(cleared.all().size(), 2);
        QVERIFY(ReviewDecisions::fromJson({}, 0, &error)->isEmpty());
    }

    void fromJsonErrors_data()
    {
        QTest::addColumn<QJsonObject>("json");
        QTest::addColumn<QString>("cause");
        QTest::newRow("record at the count")
            << entries({entry(5, QStringLiteral("accepted"))})
            << QStringLiteral("record 5 is not one of the ledger's 5 records");
        QTest::newRow("negative record") << entries({entry(-1, QStringLiteral("accepted"))})
                                         << QStringLiteral("record -1 is not one");
        QTest::newRow("fractional record") << entries({entry(1.5, QStringLiteral("accepted"))})
                                           << QStringLiteral("record 1.5 is not one");
        QTest::newRow("record as text") << entries({entry(QStringLiteral("2"), "accepted")})
                                        << QStringLiteral("record 2 is not one");
        QTest::newRow("unknown verdict")
            << entries({entry(1, QStringLiteral("accepted")), entry(2, QStringLiteral("maybe"))})
            << QStringLiteral("record 2 has an unknown verdict \"maybe\"");
        QTest::newRow("records not an array") << QJsonObject{{QStringLiteral("records"), 3}}
                                              << QStringLiteral("\"records\" is not an array");
    }

    void fromJsonErrors()
    {
        QFETCH(QJsonObject, json);
        QFETCH(QString, cause);
        QString error;
        QVERIFY(!ReviewDecisions::fromJson(json, 5, &error));
        QVERIFY2(error.contains(cause), qPrintable(error));
    }

    void csvQuotesWhatItMust()
    {
        QCOMPARE(csvField(QStringLiteral("plain text")), QStringLiteral("plain text"));
        QCOMPARE(csvField(QStringLiteral("a, b")), QStringLiteral("\"a, b\""));
        QCOMPARE(csvField(QStringLiteral("say \"hi\"")), QStringLiteral("\"say \"\"hi\"\"\""));
        QCOMPARE(csvField(QStringLiteral("two\nlines")), QStringLiteral("\"two\nlines\""));
        QCOMPARE(csvField(QString()), QString());
    }

    void csvHasOneRowPerRecord()
    {
        ReviewDecisions d;
        d.setDecision(1, {ReviewVerdict::Flagged, QStringLiteral("gone, \"really\"")});
        const QString csv = reviewCsv(threeRecords(), d);
        const QStringList lines = csv.split(QStringLiteral("\r\n"));
        QCOMPARE(lines.size(), 5); // header, three records, the empty rest after the last CRLF
        QCOMPARE(lines[0],
                 QStringLiteral("record,kind,inputs,outputs,x,y,z,size,size_meaning,verdict,note"));
        QCOMPARE(lines[1], QStringLiteral("0,corner_merge,\"c1, c2\",,1.5,-2,3.25,12.5,distance,"
                                          "open,"));
        QCOMPARE(lines[2], QStringLiteral("1,surface_lost,H1,,0,0,0,0.25,area,flagged,"
                                          "\"gone, \"\"really\"\"\""));
        QCOMPARE(lines[3], QStringLiteral("2,line_lost,,,0,0,0,0,,open,"));
        QCOMPARE(lines[4], QString());
    }

    void csvWriteIsAtomic()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("review.csv"));
        writeReviewCsv(path, threeRecords(), {});
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(file.readAll()), reviewCsv(threeRecords(), {}));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);
        QVERIFY_THROWS_EXCEPTION(
            FileError,
            writeReviewCsv(dir.filePath(QStringLiteral("no/such/dir.csv")), threeRecords(), {}));
    }
};

QTEST_GUILESS_MAIN(TestReviewDecisions)

#include "test_review_decisions.moc"
