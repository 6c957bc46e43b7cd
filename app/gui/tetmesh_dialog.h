// Parameters of the TetGen comparison meshes (thesis §5.2), one field per entry of
// tetgenParamTable(): the radius-edge quality bound, an optional maximum tet volume, the time and
// memory limits of each run, whether TetGen may refine the surfaces (and merge their coplanar
// triangles), and whether the remesh is tetrahedralised beside the input (the default when there
// is one).
#pragma once

#include "param_form.h"
#include "volume/tetgen_runner.h"

#include <QDialog>

class QRadioButton;

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
    ParamFields<TetgenParams> m_fields;
    QRadioButton *m_both;
    QRadioButton *m_inputOnly;
};

} // namespace stratamesh
