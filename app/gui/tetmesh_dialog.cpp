#include "tetmesh_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace stratamesh {

TetmeshDialog::TetmeshDialog(bool hasRemesh, double diagonal, QWidget *parent)
    : QDialog(parent), m_quality(new QDoubleSpinBox(this)), m_maxVolume(new QDoubleSpinBox(this)),
      m_refineSurfaces(new QCheckBox(tr("Let TetGen &refine the surfaces"), this)),
      m_timeLimit(new QSpinBox(this)), m_both(new QRadioButton(tr("Input and &remesh"), this)),
      m_inputOnly(new QRadioButton(tr("&Input only"), this))
{
    setObjectName(QStringLiteral("TetmeshDialog"));
    setWindowTitle(tr("Tetrahedralise"));
    const TetgenParams defaults;
    m_quality->setDecimals(3);
    m_quality->setRange(0.0, 10.0);
    m_quality->setSingleStep(0.1);
    m_quality->setValue(defaults.quality);
    m_quality->setSpecialValueText(tr("Off"));
    m_quality->setToolTip(tr("Largest circumradius to shortest edge ratio TetGen accepts (its q "
                             "switch); 0 turns quality refinement off."));
    // Volumes of a real model run to 1e9 m³ and more: the spin box follows the model's scale.
    const double scale = diagonal > 0.0 ? diagonal * diagonal * diagonal : 1.0;
    const int decimals = std::clamp(int(std::ceil(6.0 - std::log10(scale))), 0, 8);
    m_maxVolume->setDecimals(decimals);
    m_maxVolume->setRange(0.0, scale);
    m_maxVolume->setValue(0.0);
    m_maxVolume->setSpecialValueText(tr("None"));
    m_maxVolume->setToolTip(
        tr("Largest volume of a tetrahedron (TetGen's a switch); 0 sets none."));
    m_refineSurfaces->setToolTip(
        tr("Without it every surface triangle is kept as it is (TetGen's Y "
           "switch), so the meshes show what the surfaces themselves give."));
    m_timeLimit->setRange(0, 86400);
    m_timeLimit->setValue(int(kDefaultTimeLimit));
    m_timeLimit->setSuffix(tr(" s"));
    m_timeLimit->setSpecialValueText(tr("None"));
    m_timeLimit->setToolTip(tr("TetGen is stopped after this time on each model; a raw input model "
                               "can keep it busy for hours."));

    auto *models = new QGroupBox(tr("Models"), this);
    auto *modelsLayout = new QVBoxLayout(models);
    modelsLayout->addWidget(m_both);
    modelsLayout->addWidget(m_inputOnly);
    m_both->setEnabled(hasRemesh);
    m_both->setChecked(hasRemesh);
    m_inputOnly->setChecked(!hasRemesh);
    if (!hasRemesh)
        m_both->setToolTip(tr("Remesh the model first"));

    auto *options = new QFormLayout;
    options->addRow(tr("&Quality (radius-edge ratio):"), m_quality);
    options->addRow(tr("&Maximum tet volume:"), m_maxVolume);
    options->addRow(tr("&Time limit per model:"), m_timeLimit);
    options->addRow(m_refineSurfaces);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Tetrahedralise"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(models);
    layout->addLayout(options);
    layout->addWidget(buttons);
}

TetgenParams TetmeshDialog::params() const
{
    TetgenParams p;
    p.quality = m_quality->value();
    p.maxVolume = m_maxVolume->value();
    p.refineSurfaces = m_refineSurfaces->isChecked();
    p.timeLimitSeconds = m_timeLimit->value();
    return p;
}

void TetmeshDialog::setParams(const TetgenParams &p)
{
    m_quality->setValue(p.quality);
    m_maxVolume->setValue(p.maxVolume);
    m_refineSurfaces->setChecked(p.refineSurfaces);
    m_timeLimit->setValue(int(std::lround(std::min(p.timeLimitSeconds, 86400.0))));
}

bool TetmeshDialog::bothModels() const
{
    return m_both->isEnabled() && m_both->isChecked();
}

} // namespace stratamesh
