#include "common/error.h"
#include "quality/histogram.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace stratamesh;

class TestHistogram : public QObject {
    Q_OBJECT
private slots:
    void binsAreHalfOpenExceptTheLast()
    {
        Histogram h({0.0, 1.0, 2.0, 4.0});
        QCOMPARE(h.binCount(), std::size_t(3));
        for (double v : {0.0, 0.5, 1.0, 1.999, 2.0, 4.0})
            h.add(v);
        QCOMPARE(h.counts(), (std::vector<std::size_t>{2, 2, 2}));
        QCOMPARE(h.total(), std::size_t(6));
        QCOMPARE(h.below(), std::size_t(0));
        QCOMPARE(h.above(), std::size_t(0));
        QVERIFY(std::abs(h.fraction(1) - 1.0 / 3.0) < 1e-15);
    }

    void outsideValuesAreKeptApart()
    {
        Histogram h({0.0, 1.0});
        h.add(-0.1);
        h.add(1.0000001);
        h.add(std::numeric_limits<double>::quiet_NaN());
        h.add(0.25);
        QCOMPARE(h.counts(), (std::vector<std::size_t>{1}));
        QCOMPARE(h.below(), std::size_t(2));
        QCOMPARE(h.above(), std::size_t(1));
        QCOMPARE(h.total(), std::size_t(4));
        QVERIFY(std::abs(h.fraction(0) - 0.25) < 1e-15);
    }

    void uniformEdgesAreExact()
    {
        const Histogram h = Histogram::uniform(0.0, 60.0, 12);
        QCOMPARE(h.edges().size(), std::size_t(13));
        QCOMPARE(h.edges().front(), 0.0);
        QCOMPARE(h.edges()[3], 15.0);
        QCOMPARE(h.edges().back(), 60.0);
    }

    void badEdgesThrow()
    {
        QVERIFY_THROWS_EXCEPTION(InputError, Histogram({1.0}));
        QVERIFY_THROWS_EXCEPTION(InputError, Histogram({0.0, 1.0, 1.0}));
        QVERIFY_THROWS_EXCEPTION(InputError, Histogram({0.0, 2.0, 1.0}));
        QVERIFY_THROWS_EXCEPTION(InputError,
                                 Histogram({0.0, std::numeric_limits<double>::infinity()}));
        QVERIFY_THROWS_EXCEPTION(InputError, Histogram::uniform(0.0, 1.0, 0));
        const Histogram empty({0.0, 1.0});
        QCOMPARE(empty.fraction(0), 0.0);
    }
};

QTEST_GUILESS_MAIN(TestHistogram)
#include "test_histogram.moc"
