#include "complexity_dialog.h"

#include "params/param_tables.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace stratamesh {

ComplexityDialog::ComplexityDialog(QWidget *parent)
    : QDialog(parent), m_fields(complexityParamTable(), 0.0, this)
{
    setObjectName(QStringLiteral("ComplexityDialog"));
    setWindowTitle(tr("Complexity Analysis"));
    // One number of cells here (a heat map shows one diagram), the middle one of the thesis'.
    setParamFieldValue(m_fields.field("cells"), kDefaultCells);

    auto *form = new QFormLayout;
    m_fields.addRows(form);

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
    m_fields.read(p);
    return p;
}

void ComplexityDialog::setParams(const ComplexityParams &p)
{
    m_fields.write(p);
}

} // namespace stratamesh
