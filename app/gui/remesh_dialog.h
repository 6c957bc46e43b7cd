// Parameters of a remeshing (thesis chapter 4): the resolution as a number of sites or a target
// edge length, d_resolution (Alg 4.2 step 4), CVT iterations, seed, adaptive density (Fig 4.19).
#pragma once

#include "remesh/surface_remesher.h"

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QSpinBox;

namespace stratamesh {

class RemeshDialog : public QDialog {
    Q_OBJECT
public:
    // `diagonal`: bounding-box diagonal of the model, to give the lengths a sensible scale.
    explicit RemeshDialog(double diagonal, QWidget *parent = nullptr);

    RemeshParams params() const;
    void setParams(const RemeshParams &params);

    static constexpr int kDefaultSites = 5000;

private:
    void updateEnabled();

    QRadioButton *m_bySites;
    QRadioButton *m_byLength;
    QSpinBox *m_sites;
    QDoubleSpinBox *m_edgeLength;
    QDoubleSpinBox *m_dResolution;
    QDoubleSpinBox *m_stripFactor;
    QSpinBox *m_iterations;
    QSpinBox *m_seed;
    QCheckBox *m_adaptive;
};

} // namespace stratamesh
