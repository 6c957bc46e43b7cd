#include "remesh_dialog.h"

#include "params/param_tables.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace stratamesh {

RemeshDialog::RemeshDialog(double diagonal, QWidget *parent)
    : RemeshDialog(diagonal, remeshParamTable(), parent)
{
}

RemeshDialog::RemeshDialog(double diagonal, const ParamTable<RemeshParams> &table, QWidget *parent)
    : QDialog(parent), m_fields(table, diagonal, this),
      m_bySites(new QRadioButton(paramLabel(table.info("sites")), this)),
      m_byLength(new QRadioButton(paramLabel(table.info("edge_length")), this)),
      m_sites(m_fields.field("sites")), m_edgeLength(m_fields.field("edge_length"))
{
    setObjectName(QStringLiteral("RemeshDialog"));
    setWindowTitle(tr("Remesh Model"));
    const double scale = diagonal > 0.0 ? diagonal : 1.0;

    // The resolution is one of two: the radio buttons choose, the other stays 0.
    auto *sites = static_cast<QSpinBox *>(m_sites);
    sites->setValue(kDefaultSites);
    auto *edgeLength = static_cast<QDoubleSpinBox *>(m_edgeLength);
    edgeLength->setMinimum(std::pow(10.0, -edgeLength->decimals()));
    edgeLength->setValue(scale / 50.0);
    m_bySites->setChecked(true);
    // Beyond a tenth of the model, d_resolution would merge features across it (refused).
    if (auto *d = qobject_cast<QDoubleSpinBox *>(m_fields.field("d_resolution")))
        d->setMaximum(kMaxDResolutionFraction * scale);

    auto *resolution = new QGroupBox(tr("Resolution"), this);
    auto *grid = new QGridLayout(resolution);
    grid->addWidget(m_bySites, 0, 0);
    grid->addWidget(m_sites, 0, 1);
    grid->addWidget(m_byLength, 1, 0);
    grid->addWidget(m_edgeLength, 1, 1);

    auto *options = new QFormLayout;
    m_fields.addRows(options, {"sites", "edge_length"});

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Remesh"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(resolution);
    layout->addLayout(options);
    layout->addWidget(buttons);

    connect(m_bySites, &QRadioButton::toggled, this, &RemeshDialog::updateEnabled);
    connect(sites, &QSpinBox::valueChanged, this, &RemeshDialog::updateEstimate);
    updateEnabled();
}

RemeshParams RemeshDialog::params() const
{
    RemeshParams p;
    m_fields.read(p);
    if (m_bySites->isChecked())
        p.edgeLength = 0.0;
    else
        p.sites = 0;
    return p;
}

void RemeshDialog::setParams(const RemeshParams &p)
{
    if (p.sites > 0) {
        m_bySites->setChecked(true);
        setParamFieldValue(m_sites, p.sites);
    } else if (p.edgeLength > 0.0) {
        m_byLength->setChecked(true);
        setParamFieldValue(m_edgeLength, p.edgeLength);
    }
    m_fields.write(p, {"sites", "edge_length"});
    updateEnabled();
}

void RemeshDialog::setModelArea(double area)
{
    m_area = area;
    updateEstimate();
}

void RemeshDialog::updateEstimate()
{
    if (!m_bySites->isChecked() || m_area <= 0.0)
        return;
    const double length = edgeLengthForSites(m_area, int(paramFieldValue(m_sites)));
    if (length > 0.0)
        setParamFieldValue(m_edgeLength, length);
}

void RemeshDialog::updateEnabled()
{
    m_sites->setEnabled(m_bySites->isChecked());
    m_edgeLength->setEnabled(m_byLength->isChecked());
    updateEstimate();
}

} // namespace stratamesh
