// Table 3.4 statistics and the variation coefficient of Table 3.3.
#include "complexity/count_statistics.h"

#include <QtTest>

using namespace stratamesh;

class TestCountStatistics : public QObject {
    Q_OBJECT
private slots:
    void quantilesByNearestRank()
    {
        std::vector<int> values;
        for (int i = 1; i <= 100; ++i)
            values.push_back(i);
        const CountStatistics s = countStatistics(values);
        QCOMPARE(s.cells, 100);
        QCOMPARE(s.q10, 10);
        QCOMPARE(s.q50, 50);
        QCOMPARE(s.q90, 90);
        QCOMPARE(s.max, 100);
        QVERIFY(std::abs(s.mean - 50.5) < 1e-12);
        const CountStatistics small = countStatistics({3, 1, 2});
        QCOMPARE(small.q10, 1);
        QCOMPARE(small.q50, 2);
        QCOMPARE(small.q90, 3);
        const CountStatistics none = countStatistics({});
        QCOMPARE(none.cells, 0);
        QCOMPARE(none.max, 0);
    }

    void variation()
    {
        QVERIFY(std::abs(variationCoefficient({1.0, 2.0, 3.0}) - 0.5) < 1e-12); // std 1, mean 2
        QCOMPARE(variationCoefficient({4.0, 4.0, 4.0}), 0.0);
        QCOMPARE(variationCoefficient({7.0}), 0.0);
        const CountStatistics s = countStatistics({1, 1, 1, 5});
        QVERIFY(std::abs(s.varCoeff - 1.0) < 1e-12); // mean 2, sample std 2
    }
};

QTEST_GUILESS_MAIN(TestCountStatistics)
#include "test_count_statistics.moc"
