// Input vs output of a remeshing in the rows of thesis Table 4.2 (§4.5): sizes, entity counts
// (box excluded), smallest angle, % of triangles with an angle < 30°, mean quality Q, and the
// Hausdorff distance in % of the bounding-box diagonal. One line per measure, one column per
// model, as the figures are compared side by side. The figures come from core/quality.
#pragma once

#include "quality/model_comparison.h"

#include <QWidget>

#include <optional>

class QLabel;
class QTableWidget;
class QTabWidget;

namespace stratamesh {

class HistogramChart;

class ComparisonTable : public QWidget {
    Q_OBJECT
public:
    enum Row {
        VerticesRow,
        TrianglesRow,
        SurfacesRow,
        LinesRow,
        CornersRow,
        MinAngleRow,
        Below30Row,
        MeanQualityRow,
        HausdorffRow,
        SamplingTimeRow,
        MeshTimeRow,
        RowCount
    };
    enum Column { InputColumn, OutputColumn, ColumnCount };

    explicit ComparisonTable(QWidget *parent = nullptr);

    // std::nullopt clears.
    void setComparison(std::optional<ModelComparison> comparison);
    // The columns' and histograms' names: "Input" and "Output" when empty, "Run 1" and "Run 3"
    // when two runs are compared.
    void setColumnNames(const QString &first, const QString &second);
    bool hasComparison() const { return m_comparison.has_value(); }
    // Text of a cell as shown.
    QString cellText(Row row, Column column) const;
    QString columnName(Column column) const;
    // Min angle and Q distributions of both models, below the table.
    HistogramChart *minAngleChart() const { return m_minAngle; }
    HistogramChart *qualityChart() const { return m_quality; }
    // Wide enough for the measure names and both columns of figures.
    QSize sizeHint() const override;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fill();

    std::optional<ModelComparison> m_comparison;
    QString m_firstName;
    QString m_secondName;
    QTableWidget *m_table;
    QLabel *m_caption;
    QTabWidget *m_charts;
    HistogramChart *m_minAngle;
    HistogramChart *m_quality;
};

} // namespace stratamesh
