// The Tetrahedra dock: what TetGen made of the input model and of its remesh under the same
// switches (thesis §5.2), as computed by the core (volume/tetgen_comparison.h): one column per
// model (tets, points, slivers, min dihedral angle, time, outcome) and the controls of the views
// (colouring, clip plane); the distributions of both are overlaid in the Quality tab
// (ComparisonTable::setTetQuality).
// A side TetGen failed on is a result like any other: its outcome and TetGen's message.
#pragma once

#include "tet_mesh_pair.h"
#include "volume/tetgen_comparison.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QTableWidget;

namespace stratamesh {

class ClipControls;

class TetmeshPanel : public QWidget {
    Q_OBJECT
public:
    enum Row { OutcomeRow, TetsRow, PointsRow, SliversRow, MinDihedralRow, TimeRow, RowCount };
    enum Column { InputColumn, RemeshColumn, ColumnCount };

    explicit TetmeshPanel(QWidget *parent = nullptr);

    // output nullptr: the input alone was tetrahedralised. input nullptr clears.
    void setSides(const TetmeshSide *input, const TetmeshSide *output);
    bool hasResult() const { return m_input.has_value(); }
    QString cellText(Row row, Column column) const;
    // One sentence per side TetGen failed on, empty when both are ok.
    QString notesText() const;

    TetColouring colouring() const;
    void setColouring(TetColouring colouring);
    bool clipEnabled() const;
    ClipAxis clipAxis() const;
    double clipFraction() const; // [0, 1]
    void setClip(bool enabled, ClipAxis axis, double fraction);

    // The translated outcome ("ok", "timed out", …) and the sentence for a failed side.
    static QString outcomeText(TetgenOutcome outcome);
    static QString failureText(TetgenOutcome outcome, const QString &message, double seconds,
                               bool input);
    QSize sizeHint() const override;

signals:
    void colouringChanged(stratamesh::TetColouring colouring);
    void clipChanged(bool enabled, stratamesh::ClipAxis axis, double fraction);

protected:
    void changeEvent(QEvent *event) override;

private:
    // What the panel shows of a side: the mesh itself stays with the views.
    struct Side {
        TetgenOutcome outcome = TetgenOutcome::Aborted;
        QString message;
        double seconds = 0.0;
        VolumeQualityStatistics quality;
    };

    void retranslate();
    void fill();

    std::optional<Side> m_input;
    std::optional<Side> m_output;
    QLabel *m_colourLabel;
    QComboBox *m_colouring;
    ClipControls *m_clip;
    QTableWidget *m_table;
    QLabel *m_notes;
};

} // namespace stratamesh
