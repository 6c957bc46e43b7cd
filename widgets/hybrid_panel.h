// The Hybrid Mesh dock: what the hybrid mesher made (thesis chapter 5, core/hybrid), as computed
// by the core: one column per cell type (cells, min and max dihedral angle, slivers for the tets),
// whether the mixed-mesh checker found the mesh valid, how many cells it found invalid and
// repaired, the time; and the controls of the view (colour by type, quality or region; the clip
// plane, placed as in the Tetrahedra dock).
#pragma once

#include "hybrid/cell_quality.h"
#include "tet_mesh_pair.h"

#include <QWidget>

#include <array>
#include <optional>

class QComboBox;
class QLabel;
class QTableWidget;

namespace stratamesh {

class ClipControls;

// The figures the dock shows, copied from the core's result so the mesh can go with the view.
struct HybridStatistics {
    std::array<TypeQuality, 3> byType; // indexed by CellType
    bool valid = false;
    std::size_t invalidFound = 0;
    std::size_t repaired = 0;
    // Where the cells come from (thesis §5.3.2, §5.3.3, transitions, TetGen's fill).
    std::size_t segmentDual = 0, vertexDual = 0, transitionPyramids = 0, fillTets = 0;
    bool fellBackToTetgen = false;
    double seconds = 0.0;
    QString message; // why the mesh is not valid
};

class HybridPanel : public QWidget {
    Q_OBJECT
public:
    enum Row { CellsRow, MinDihedralRow, MeanMinDihedralRow, MaxDihedralRow, SliversRow, RowCount };

    explicit HybridPanel(QWidget *parent = nullptr);

    // nullptr clears.
    void setStatistics(const HybridStatistics *statistics);
    bool hasResult() const { return m_statistics.has_value(); }
    QString cellText(Row row, CellType type) const;
    // Valid, invalid found, repaired and the time, one line.
    QString summaryText() const;

    TetColouring colouring() const;
    void setColouring(TetColouring colouring);
    bool clipEnabled() const;
    ClipAxis clipAxis() const;
    double clipFraction() const;
    void setClip(bool enabled, ClipAxis axis, double fraction);
    // Wide enough for the three columns of figures beside the row names.
    QSize sizeHint() const override;

signals:
    void colouringChanged(stratamesh::TetColouring colouring);
    void clipChanged(bool enabled, stratamesh::ClipAxis axis, double fraction);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fill();

    std::optional<HybridStatistics> m_statistics;
    QLabel *m_colourLabel;
    QComboBox *m_colouring;
    ClipControls *m_clip;
    QTableWidget *m_table;
    QLabel *m_summary;
};

} // namespace stratamesh
