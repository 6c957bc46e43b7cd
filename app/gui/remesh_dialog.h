// Parameters of a remeshing (thesis chapter 4), one field per entry of remeshParamTable(): the
// resolution as a number of sites or a target edge length, then d_resolution (Alg 4.2 step 4),
// thin strips, CVT iterations, seed, refinement, adaptive density (Fig 4.19), merge-all.
#pragma once

#include "param_form.h"
#include "remesh/surface_remesher.h"

#include <QDialog>

class QRadioButton;
class QSpinBox;

namespace stratamesh {

class RemeshDialog : public QDialog {
    Q_OBJECT
public:
    // `diagonal`: bounding-box diagonal of the model, to give the lengths a sensible scale.
    explicit RemeshDialog(double diagonal, QWidget *parent = nullptr);
    // The fields of `table` (tests add an entry to a copy of remeshParamTable()).
    RemeshDialog(double diagonal, const ParamTable<RemeshParams> &table, QWidget *parent = nullptr);

    RemeshParams params() const;
    void setParams(const RemeshParams &params);
    // The model's surface area (core modelArea()): while the resolution is a number of sites,
    // the greyed edge length shows what that number gives on this model.
    void setModelArea(double area);

    static constexpr int kDefaultSites = 5000;

private:
    void updateEnabled();
    void updateEstimate();

    ParamFields<RemeshParams> m_fields;
    QRadioButton *m_bySites;
    QRadioButton *m_byLength;
    QWidget *m_sites;
    QWidget *m_edgeLength;
    double m_area = 0.0;
};

} // namespace stratamesh
