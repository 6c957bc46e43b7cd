// Real models (thesis Table 3.1): counts without the box, volumes, validity.
#include "support/test_data.h"

#include "io/model_reader.h"
#include "model/model_counts.h"
#include "model/region_volume.h"
#include "model/topology.h"
#include "model/validity.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

QString text(const EntityCounts &c)
{
    return QStringLiteral("%1/%2/%3/%4").arg(c.regions).arg(c.surfaces).arg(c.lines).arg(c.corners);
}

QString summary(const ValidityReport &r)
{
    QStringList parts;
    for (const auto &[name, n] : r.counts)
        parts << QStringLiteral("%1=%2").arg(QString::fromStdString(name)).arg(n);
    for (std::size_t i = 0; i < r.problems.size() && i < 3; ++i)
        parts << QString::fromStdString(r.problems[i].message);
    return parts.join(QStringLiteral("; "));
}

} // namespace

class TestModelData : public QObject {
    Q_OBJECT

private slots:
    void thesisModels_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("withoutBox");
        // Table 3.1 (design.md §4: A2 has 12 lines in the file, the thesis prints 13).
        QTest::newRow("modelA1") << QStringLiteral("modelA1.ml") << QStringLiteral("4/3/0/0");
        QTest::newRow("modelA2") << QStringLiteral("modelA2.ml") << QStringLiteral("12/23/12/0");
        QTest::newRow("modelA5") << QStringLiteral("modelA5.ml") << QStringLiteral("12/31/30/10");
    }
    void thesisModels()
    {
        QFETCH(QString, file);
        QFETCH(QString, withoutBox);
        STRATAMESH_REQUIRE_DATA(path, file);
        const Model m = recoverTopology(readModel(path.toStdString()));
        const ModelCounts c = countEntities(m);
        QCOMPARE(text(c.withoutBox), withoutBox);

        double sum = 0.0;
        for (double v : regionVolumes(m)) {
            QVERIFY(v > 0.0);
            sum += v;
        }
        const double box = boxEnclosedVolume(m);
        QVERIFY2(std::abs(sum - box) <= 1e-9 * box,
                 qPrintable(QStringLiteral("%1 vs %2").arg(sum, 0, 'g', 17).arg(box, 0, 'g', 17)));
        // formats.md §1.6: A1/A2/A4/A5 share one box of volume 7.76229e11.
        QVERIFY(std::abs(box - 7.76229e11) < 1e-5 * box);
        QVERIFY(std::abs(universeVolume(m) + sum) <= 1e-9 * sum);

        const ValidityReport r = checkValidity(m);
        QVERIFY2(r.valid, qPrintable(summary(r)));
    }

    void notSealedCube()
    {
        STRATAMESH_REQUIRE_DATA(path, "not_sealed_cube.ml");
        const ValidityReport r = checkValidity(recoverTopology(readModel(path.toStdString())));
        QVERIFY(!r.valid);
        QCOMPARE(r.count(validity_check::notSealed), std::size_t(6)); // six squares, none touching
    }
};

QTEST_GUILESS_MAIN(TestModelData)
#include "test_model_data.moc"
