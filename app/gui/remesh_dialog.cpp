#include "remesh_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace stratamesh {

namespace {

// Decimals enough to set lengths to 1/100 000 of the model's size (d_resolution is small).
int decimalsFor(double diagonal)
{
    return diagonal > 0.0 ? std::clamp(int(std::ceil(5.0 - std::log10(diagonal))), 0, 8) : 3;
}

} // namespace

RemeshDialog::RemeshDialog(double diagonal, QWidget *parent)
    : QDialog(parent), m_bySites(new QRadioButton(tr("Number of &sites:"), this)),
      m_byLength(new QRadioButton(tr("Target &edge length:"), this)), m_sites(new QSpinBox(this)),
      m_edgeLength(new QDoubleSpinBox(this)), m_dResolution(new QDoubleSpinBox(this)),
      m_stripFactor(new QDoubleSpinBox(this)), m_iterations(new QSpinBox(this)),
      m_seed(new QSpinBox(this)),
      m_adaptive(new QCheckBox(tr("&Adaptive density (more sites near corners)"), this))
{
    setObjectName(QStringLiteral("RemeshDialog"));
    setWindowTitle(tr("Remesh Model"));
    const double scale = diagonal > 0.0 ? diagonal : 1.0;
    const int decimals = decimalsFor(scale);

    m_sites->setRange(4, 10000000);
    m_sites->setGroupSeparatorShown(true);
    m_sites->setValue(kDefaultSites);
    m_sites->setToolTip(tr("Sites spread over all the surfaces; each becomes about one vertex."));
    m_edgeLength->setDecimals(decimals);
    m_edgeLength->setRange(std::pow(10.0, -decimals), scale);
    m_edgeLength->setValue(scale / 50.0);
    m_edgeLength->setToolTip(
        tr("The number of sites is derived from the total area for this edge length."));
    m_bySites->setChecked(true);

    m_dResolution->setDecimals(decimals);
    m_dResolution->setRange(0.0, scale);
    m_dResolution->setValue(0.0);
    m_dResolution->setSpecialValueText(tr("Off"));
    m_dResolution->setToolTip(
        tr("Parts of features closer than this distance are merged (thesis Alg. 4.2, "
           "step 4); 0 keeps them apart."));
    m_stripFactor->setDecimals(2);
    m_stripFactor->setRange(0.0, 1.0);
    m_stripFactor->setSingleStep(0.05);
    m_stripFactor->setValue(RemeshParams{}.stripWidthFactor);
    m_stripFactor->setSpecialValueText(tr("Off"));
    m_stripFactor->setSuffix(tr(" × edge length"));
    m_stripFactor->setToolTip(
        tr("Surfaces narrower than this between two long lines (a small fault throw) are "
           "removed whole before remeshing, their two lines merged into one; 0 keeps them."));
    m_iterations->setRange(0, 100000);
    m_iterations->setValue(100);
    m_iterations->setToolTip(
        tr("Iterations of the centroidal Voronoi optimisation of the sites (thesis: 100)."));
    m_seed->setRange(0, 2147483647);
    m_seed->setValue(1);
    m_seed->setToolTip(
        tr("Seed of the initial random sampling: the same seed gives the same mesh."));
    m_adaptive->setToolTip(
        tr("Site density grows near corners, so small features keep more triangles "
           "(thesis Fig. 4.19)."));

    auto *resolution = new QGroupBox(tr("Resolution"), this);
    auto *grid = new QGridLayout(resolution);
    grid->addWidget(m_bySites, 0, 0);
    grid->addWidget(m_sites, 0, 1);
    grid->addWidget(m_byLength, 1, 0);
    grid->addWidget(m_edgeLength, 1, 1);

    auto *options = new QFormLayout;
    options->addRow(tr("&d_resolution:"), m_dResolution);
    options->addRow(tr("Remove thin s&trips under:"), m_stripFactor);
    options->addRow(tr("&Iterations:"), m_iterations);
    options->addRow(tr("Ra&ndom seed:"), m_seed);
    options->addRow(m_adaptive);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Remesh"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(resolution);
    layout->addLayout(options);
    layout->addWidget(buttons);

    connect(m_bySites, &QRadioButton::toggled, this, &RemeshDialog::updateEnabled);
    updateEnabled();
}

RemeshParams RemeshDialog::params() const
{
    RemeshParams p;
    if (m_bySites->isChecked())
        p.sites = m_sites->value();
    else
        p.edgeLength = m_edgeLength->value();
    p.dResolution = m_dResolution->value();
    p.stripWidthFactor = m_stripFactor->value();
    p.iterations = m_iterations->value();
    p.seed = unsigned(m_seed->value());
    p.adaptive = m_adaptive->isChecked();
    return p;
}

void RemeshDialog::setParams(const RemeshParams &p)
{
    if (p.sites > 0) {
        m_bySites->setChecked(true);
        m_sites->setValue(p.sites);
    } else if (p.edgeLength > 0.0) {
        m_byLength->setChecked(true);
        m_edgeLength->setValue(p.edgeLength);
    }
    m_dResolution->setValue(p.dResolution);
    m_stripFactor->setValue(p.stripWidthFactor);
    m_iterations->setValue(p.iterations);
    m_seed->setValue(int(std::min<unsigned>(p.seed, 2147483647u)));
    m_adaptive->setChecked(p.adaptive);
    updateEnabled();
}

void RemeshDialog::updateEnabled()
{
    m_sites->setEnabled(m_bySites->isChecked());
    m_edgeLength->setEnabled(m_byLength->isChecked());
}

} // namespace stratamesh
