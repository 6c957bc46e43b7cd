// Parameters of a complexity analysis (thesis ch. 3), one field per entry of
// complexityParamTable(): characteristic size h and angle α of the geometric measures (Table 3.2),
// number of cells, seed and Lloyd iterations of the volumetric CVT of the local measures
// (Table 3.4, Fig 3.7).
#pragma once

#include "complexity/complexity_report.h"
#include "param_form.h"

#include <QDialog>

namespace stratamesh {

class ComplexityDialog : public QDialog {
    Q_OBJECT
public:
    explicit ComplexityDialog(QWidget *parent = nullptr);

    // params().cells holds the one number of cells chosen.
    ComplexityParams params() const;
    void setParams(const ComplexityParams &params);

    static constexpr int kDefaultCells = 1000;
    static constexpr int kMaxCells = kMaxComplexityCells;

private:
    ParamFields<ComplexityParams> m_fields;
};

} // namespace stratamesh
