// The clip plane's controls of a volume-mesh panel: on/off, the section's axis and the plane's
// position across the mesh. One signal for any change, so a scene re-clips once.
#pragma once

#include "tet_mesh_pair.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QSlider;
class QTableWidget;

namespace stratamesh {

class ClipControls : public QWidget {
    Q_OBJECT
public:
    // `name` prefixes the child widgets' object names ("Tet" → TetClip, TetClipAxis, …).
    ClipControls(const QString &name, QWidget *parent = nullptr);

    bool isClipping() const;
    ClipAxis axis() const;
    double fraction() const; // 0 at the low end of the bounds, 1 at the high end
    void setClip(bool enabled, ClipAxis axis, double fraction);

signals:
    void clipChanged(bool enabled, stratamesh::ClipAxis axis, double fraction);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void emitClip();

    QCheckBox *m_clip;
    QComboBox *m_axis;
    QSlider *m_position;
};

// The read-only look of a per-type statistics table: figures right-aligned, rows sized to the
// font, columns sharing the width (each at least `minimumSection` px), every cell an item.
void setUpStatisticsTable(QTableWidget *table, int minimumSection);

} // namespace stratamesh
