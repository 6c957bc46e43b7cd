// Thesis Table 3.4 checks on the real models: Q90 = 3 at 10 000 cells on A2 and A5, every inner
// corner counted exactly once, no cell outside the model (A2 only under the sanitizers).
#include "complexity/box_elements.h"
#include "complexity/local_complexity.h"
#include "io/model_reader.h"
#include "model/topology.h"
#include "support/sanitizer.h"
#include "support/test_data.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

class TestLocalComplexityData : public QObject {
    Q_OBJECT
private slots:
    void q90At10000Cells_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("A2") << "modelA2.ml";
        if (!test::kSanitized)
            QTest::newRow("A5") << "modelA5.ml";
    }

    void q90At10000Cells()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        const Model model = recoverTopology(readModel(path.toStdString()));
        LocalComplexityParams params;
        params.cells = 10000;
        const LocalComplexity local = localComplexity(model, params);
        QCOMPARE(local.outsideCells, 0);
        QCOMPARE(local.statistics.cells, 10000);
        QCOMPARE(local.statistics.q10, 1);
        QCOMPARE(local.statistics.q50, 1);
        QCOMPARE(local.statistics.q90, 3);
        // The cells tile the box.
        double volume = 0.0;
        for (const ConvexPolyhedron &cell : local.cvt.cells)
            volume += cell.volume();
        QVERIFY(std::abs(volume - local.cvt.box.volume()) < 1e-9 * local.cvt.box.volume());
        int corners = 0;
        for (const CellElementCounts &c : local.counts) {
            QVERIFY(c.regions >= 1);
            corners += c.corners;
        }
        QCOMPARE(corners, static_cast<int>(boxElements(model).innerCorners().size()));
        qInfo("%s 10000 cells: Q10 %d Q50 %d Q90 %d max %d mean %.3f var %.3f (CVT %.1f s, counts "
              "%.1f s)",
              qPrintable(file), local.statistics.q10, local.statistics.q50, local.statistics.q90,
              local.statistics.max, local.statistics.mean, local.statistics.varCoeff,
              local.cvtSeconds, local.countSeconds);
    }
};

QTEST_GUILESS_MAIN(TestLocalComplexityData)
#include "test_local_complexity_data.moc"
