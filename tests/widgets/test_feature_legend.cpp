// The legend over a 3D view gives up detail as its view shrinks: two views side by side on a
// 1280-pixel window leave each about 320 pixels, where the full legend covered the model.
#include "feature_legend.h"

#include <QtTest>

using namespace stratamesh;

namespace {

// Six horizons, seven faults and the box, as the bundled sample.
std::vector<LegendEntry> sampleEntries()
{
    LegendEntry horizons;
    horizons.type = FeatureType::Horizon;
    horizons.color = Qt::green;
    horizons.featureCount = 3;
    horizons.surfaceCount = 6;
    horizons.featureNames = {QStringLiteral("H1"), QStringLiteral("H2"), QStringLiteral("H3")};
    LegendEntry faults;
    faults.type = FeatureType::Fault;
    faults.color = Qt::red;
    faults.featureCount = 1;
    faults.surfaceCount = 7;
    faults.featureNames = {QStringLiteral("F1")};
    LegendEntry box;
    box.type = FeatureType::Boundary;
    box.color = Qt::gray;
    box.surfaceCount = 28;
    return {horizons, faults, box};
}

} // namespace

class TestFeatureLegend : public QObject {
    Q_OBJECT
private slots:
    void aWideViewShowsEveryFeature()
    {
        QWidget view;
        view.resize(1200, 800);
        FeatureLegend legend(&view);
        legend.setEntries(sampleEntries(), false);
        QCOMPARE(legend.detail(), FeatureLegend::Detail::Full);
        const QSize full = legend.size();
        QVERIFY(legend.isVisibleTo(&view));
        // Title, 3 type rows and 4 feature rows: 8 lines.
        QVERIFY2(full.height() > 7 * legend.fontMetrics().height(),
                 qPrintable(QString::number(full.height())));
    }

    void aNarrowViewGetsASmallerLegendWithEveryType()
    {
        QWidget view;
        view.resize(1200, 800);
        FeatureLegend legend(&view);
        legend.setEntries(sampleEntries(), false);
        view.show(); // a hidden widget gets its resize events only when shown
        const QSize full = legend.size();
        for (const QSize viewSize : {QSize(320, 430), QSize(260, 300), QSize(500, 250)}) {
            view.resize(viewSize); // the legend follows its view's resize events
            QCoreApplication::sendPostedEvents();
            QVERIFY2(
                legend.detail() != FeatureLegend::Detail::Full,
                qPrintable(QStringLiteral("%1×%2").arg(viewSize.width()).arg(viewSize.height())));
            QVERIFY(legend.width() < full.width() || legend.height() < full.height());
            QVERIFY(legend.height() <= FeatureLegend::kMaxHeightShare * viewSize.height());
            QVERIFY(legend.width() <= FeatureLegend::kMaxWidthShare * viewSize.width()
                    || legend.detail() == FeatureLegend::Detail::Names);
        }
        // Wide again: everything back.
        view.resize(1200, 800);
        QCOMPARE(legend.detail(), FeatureLegend::Detail::Full);
        QCOMPARE(legend.size(), full);
    }

    // The type names alone still fit three types in a 320×430 view within the budget.
    void typeNamesFitTheSideBySideViews()
    {
        QWidget view;
        view.resize(320, 430);
        FeatureLegend legend(&view);
        legend.setEntries(sampleEntries(), true);
        QVERIFY(legend.width() <= FeatureLegend::kMaxWidthShare * 320);
        QVERIFY(legend.height() <= FeatureLegend::kMaxHeightShare * 430);
    }
};

QTEST_MAIN(TestFeatureLegend)
#include "test_feature_legend.moc"
