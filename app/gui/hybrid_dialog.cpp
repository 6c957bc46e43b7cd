#include "hybrid_dialog.h"

#include "params/param_tables.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace stratamesh {

HybridDialog::HybridDialog(double diagonal, QWidget *parent)
    : QDialog(parent), m_fields(hybridParamTable(), diagonal, this)
{
    setObjectName(QStringLiteral("HybridDialog"));
    setWindowTitle(tr("Hybrid Mesh"));

    auto *options = new QFormLayout;
    m_fields.addRows(options);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Build Mesh"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(options);
    layout->addWidget(buttons);
}

HybridParams HybridDialog::params() const
{
    HybridParams p;
    m_fields.read(p);
    return p;
}

void HybridDialog::setParams(const HybridParams &p)
{
    m_fields.write(p);
}

} // namespace stratamesh
