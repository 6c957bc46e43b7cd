// Parameters of the hybrid mesh (thesis chapter 5), one field per entry of hybridParamTable():
// sites, thin-layer ratio, CVT iterations, seed, quad warp bound, TetGen's quality bound.
#pragma once

#include "hybrid/hybrid_mesher.h"
#include "param_form.h"

#include <QDialog>

namespace stratamesh {

class HybridDialog : public QDialog {
    Q_OBJECT
public:
    // `diagonal`: bounding-box diagonal of the model, for fields given as lengths.
    explicit HybridDialog(double diagonal, QWidget *parent = nullptr);

    HybridParams params() const;
    void setParams(const HybridParams &params);

private:
    ParamFields<HybridParams> m_fields;
};

} // namespace stratamesh
