#include "tetmesh_dialog.h"

#include "params/param_tables.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace stratamesh {

TetmeshDialog::TetmeshDialog(bool hasRemesh, double diagonal, QWidget *parent)
    : QDialog(parent), m_fields(tetgenParamTable(), diagonal, this),
      m_both(new QRadioButton(tr("Input and &remesh"), this)),
      m_inputOnly(new QRadioButton(tr("&Input only"), this))
{
    setObjectName(QStringLiteral("TetmeshDialog"));
    setWindowTitle(tr("Tetrahedralise"));
    // A raw input model can keep TetGen busy for hours: the GUI sets a limit, the CLI none.
    setParamFieldValue(m_fields.field("time_limit"), kDefaultTimeLimit);

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
    m_fields.addRows(options);

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
    m_fields.read(p);
    return p;
}

void TetmeshDialog::setParams(const TetgenParams &p)
{
    m_fields.write(p);
}

bool TetmeshDialog::bothModels() const
{
    return m_both->isEnabled() && m_both->isChecked();
}

} // namespace stratamesh
