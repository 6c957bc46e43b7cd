// The Complexity dock: the measures of thesis chapter 3 for one model, as computed by the core
// (complexity/complexity_report.h) — global counts (Table 3.1), geometric complexity per element
// type (Table 3.2), size variation coefficients (Table 3.3), and the statistics of the number of
// elements per cell of one local run (Table 3.4) — with the heat map's controls (Fig 3.7).
#pragma once

#include "complexity/complexity_report.h"

#include <QWidget>

#include <optional>

class QCheckBox;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace stratamesh {

class ComplexityPanel : public QWidget {
    Q_OBJECT
public:
    enum GlobalRow { CountsRow, GeometricRow, VariationRow, GlobalRowCount };
    enum GlobalColumn {
        RegionsColumn,
        SurfacesColumn,
        LinesColumn,
        CornersColumn,
        TotalColumn,
        GlobalColumnCount
    };
    enum LocalRow { CellsRow, Q10Row, Q50Row, Q90Row, MaxRow, MeanRow, VarCoeffRow, LocalRowCount };

    explicit ComplexityPanel(QWidget *parent = nullptr);

    // The report (its first local run is shown) and its parameters; std::nullopt clears.
    void setReport(std::optional<ComplexityReport> report, const ComplexityParams &params = {});
    bool hasReport() const { return m_report.has_value(); }
    QString globalText(GlobalRow row, GlobalColumn column) const;
    QString localText(LocalRow row) const;

    // Heat map controls: cells drawn when their count is at least the threshold.
    int threshold() const;
    void setThreshold(int threshold);
    bool heatMapVisible() const;
    void setHeatMapVisible(bool visible);
    // "shown of total cells drawn", under the controls.
    void setShownCells(int shown, int total);
    QSpinBox *thresholdBox() const { return m_threshold; }
    QCheckBox *heatMapBox() const { return m_showHeatMap; }
    QSize sizeHint() const override;

    static constexpr int kDefaultThreshold = 3;

signals:
    void thresholdChanged(int threshold);
    void heatMapVisibleChanged(bool visible);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fill();

    std::optional<ComplexityReport> m_report;
    ComplexityParams m_params;
    QLabel *m_globalCaption;
    QTableWidget *m_global;
    QLabel *m_localCaption;
    QTableWidget *m_local;
    QCheckBox *m_showHeatMap;
    QLabel *m_thresholdLabel;
    QSpinBox *m_threshold;
    QLabel *m_shown;
    int m_shownCells = 0;
    int m_totalCells = 0;
};

} // namespace stratamesh
