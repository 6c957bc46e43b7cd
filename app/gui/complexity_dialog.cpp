#include "complexity_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace stratamesh {

ComplexityDialog::ComplexityDialog(QWidget *parent)
    : QDialog(parent), m_h(new QDoubleSpinBox(this)), m_alpha(new QDoubleSpinBox(this)),
      m_cells(new QSpinBox(this)), m_seed(new QSpinBox(this))
{
    setObjectName(QStringLiteral("ComplexityDialog"));
    setWindowTitle(tr("Complexity Analysis"));
    const ComplexityParams defaults;
    m_h->setObjectName(QStringLiteral("h"));
    m_h->setDecimals(3);
    m_h->setRange(0.001, 1e9);
    m_h->setValue(defaults.geometric.h);
    m_h->setSuffix(tr(" m"));
    m_h->setToolTip(
        tr("Characteristic size: elements smaller than h (h² for surfaces, h³ for regions) are "
           "complex (thesis Table 3.2)."));
    m_alpha->setObjectName(QStringLiteral("alpha"));
    m_alpha->setDecimals(1);
    m_alpha->setRange(0.1, 180.0);
    m_alpha->setValue(defaults.geometric.alphaDegrees);
    m_alpha->setSuffix(QStringLiteral("°"));
    m_alpha->setToolTip(
        tr("Angles between elements smaller than α are complex (thesis Table 3.2)."));
    m_cells->setObjectName(QStringLiteral("cells"));
    m_cells->setRange(1, kMaxCells);
    m_cells->setGroupSeparatorShown(true);
    m_cells->setValue(kDefaultCells);
    m_cells->setToolTip(
        tr("Cells of the volumetric Voronoi diagram in which model elements are counted "
           "(thesis Table 3.4: 100, 1000, 10000)."));
    m_seed->setObjectName(QStringLiteral("seed"));
    m_seed->setRange(0, 2147483647);
    m_seed->setValue(int(defaults.seed));
    m_seed->setToolTip(tr("Seed of the initial random sites: the same seed gives the same cells."));

    auto *form = new QFormLayout;
    form->addRow(tr("Characteristic size &h:"), m_h);
    form->addRow(tr("&Angle α:"), m_alpha);
    form->addRow(tr("Number of &cells:"), m_cells);
    form->addRow(tr("Ra&ndom seed:"), m_seed);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Analyse"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

ComplexityParams ComplexityDialog::params() const
{
    ComplexityParams p;
    p.geometric.h = m_h->value();
    p.geometric.alphaDegrees = m_alpha->value();
    p.cells = {m_cells->value()};
    p.seed = std::uint64_t(m_seed->value());
    return p;
}

void ComplexityDialog::setParams(const ComplexityParams &p)
{
    m_h->setValue(p.geometric.h);
    m_alpha->setValue(p.geometric.alphaDegrees);
    if (!p.cells.empty())
        m_cells->setValue(p.cells.front());
    m_seed->setValue(int(std::min<std::uint64_t>(p.seed, 2147483647u)));
}

} // namespace stratamesh
