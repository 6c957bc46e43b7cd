// Input vs output of a remeshing in the rows of thesis Table 4.2 (§4.5): sizes, entity counts
// (box excluded), smallest angle, % of triangles with an angle < 30°, mean quality Q, and the
// Hausdorff distance in % of the bounding-box diagonal. One line per measure, one column per
// model, as the figures are compared side by side. The figures come from core/quality. Below,
// the distributions of both overlaid in the same bins: min angle and Q of the triangles and, once
// TetGen meshed them, min dihedral angle and radius ratio of the tets (the window's Quality tab).
#pragma once

#include "quality/model_comparison.h"
#include "volume/tet_quality.h"

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
    // The tets' min dihedral and radius ratio 3r/R distributions of TetGen's meshes of the input
    // and of the remesh, as two more tabs; `input` nullptr removes them, `remesh` nullptr shows
    // the input alone. A side TetGen failed on has empty histograms in the same bins.
    void setTetQuality(const VolumeQualityStatistics *input, const VolumeQualityStatistics *remesh);
    // Brings the min dihedral tab to the front (after a TetGen run).
    void showTetQuality();
    bool hasTetQuality() const { return m_tetInput.has_value(); }
    HistogramChart *minDihedralChart() const { return m_minDihedral; }
    HistogramChart *radiusRatioChart() const { return m_radiusRatio; }
    QTabWidget *chartTabs() const { return m_charts; }
    // Wide enough for the measure names and both columns of figures.
    QSize sizeHint() const override;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fill();

    std::optional<ModelComparison> m_comparison;
    std::optional<VolumeQualityStatistics> m_tetInput;
    std::optional<VolumeQualityStatistics> m_tetRemesh;
    QString m_firstName;
    QString m_secondName;
    QTableWidget *m_table;
    QLabel *m_caption;
    QTabWidget *m_charts;
    HistogramChart *m_minAngle;
    HistogramChart *m_quality;
    HistogramChart *m_minDihedral;
    HistogramChart *m_radiusRatio;
};

} // namespace stratamesh
