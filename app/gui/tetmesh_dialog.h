// Parameters of the TetGen comparison meshes (thesis §5.2): the radius-edge quality bound, an
// optional maximum tet volume, whether TetGen may refine the surfaces, the time limit of each
// run, and whether the remesh is tetrahedralised beside the input (the default when there is one).
#pragma once

#include "volume/tetgen_runner.h"

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QRadioButton;
class QSpinBox;

namespace stratamesh {

class TetmeshDialog : public QDialog {
    Q_OBJECT
public:
    // `hasRemesh`: a remeshed model exists, so both can be run. `diagonal`: bounding-box diagonal
    // of the model, to scale the maximum volume.
    TetmeshDialog(bool hasRemesh, double diagonal, QWidget *parent = nullptr);

    TetgenParams params() const;
    void setParams(const TetgenParams &params);
    // True: input and remesh; false: the input alone.
    bool bothModels() const;

    static constexpr double kDefaultTimeLimit = 600.0;

private:
    QDoubleSpinBox *m_quality;
    QDoubleSpinBox *m_maxVolume;
    QCheckBox *m_refineSurfaces;
    QSpinBox *m_timeLimit;
    QRadioButton *m_both;
    QRadioButton *m_inputOnly;
};

} // namespace stratamesh
