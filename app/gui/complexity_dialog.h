// Parameters of a complexity analysis (thesis ch. 3): characteristic size h and angle α of the
// geometric measures (Table 3.2), number of cells and seed of the volumetric CVT of the local
// measures (Table 3.4, Fig 3.7).
#pragma once

#include "complexity/complexity_report.h"

#include <QDialog>

class QDoubleSpinBox;
class QSpinBox;

namespace stratamesh {

class ComplexityDialog : public QDialog {
    Q_OBJECT
public:
    explicit ComplexityDialog(QWidget *parent = nullptr);

    // params().cells holds the one number of cells chosen.
    ComplexityParams params() const;
    void setParams(const ComplexityParams &params);

    static constexpr int kDefaultCells = 1000;
    static constexpr int kMaxCells = 200000;

private:
    QDoubleSpinBox *m_h;
    QDoubleSpinBox *m_alpha;
    QSpinBox *m_cells;
    QSpinBox *m_seed;
};

} // namespace stratamesh
