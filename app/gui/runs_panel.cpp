#include "runs_panel.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stratamesh {

namespace {

enum Column {
    Run,
    Parameters,
    Sites,
    Vertices,
    Triangles,
    Valid,
    Hausdorff,
    MeanQ,
    Reviewed,
    Count
};

} // namespace

RunsPanel::RunsPanel(QWidget *parent)
    : QWidget(parent), m_table(new QTableWidget(this)), m_compare(new QPushButton(this)),
      m_input(new QPushButton(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_compare);
    buttons->addWidget(m_input);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_compare->setObjectName(QStringLiteral("CompareRunsButton"));
    m_input->setObjectName(QStringLiteral("InputVsOutputButton"));
    m_compare->setEnabled(false);
    m_input->setEnabled(false);
    connect(m_compare, &QPushButton::clicked, this, &RunsPanel::chooseComparison);
    connect(m_input, &QPushButton::clicked, this, &RunsPanel::inputChosen);
    m_table->setColumnCount(Count);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->setObjectName(QStringLiteral("RunsTable"));
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        const QList<QTableWidgetItem *> selected = m_table->selectedItems();
        if (!selected.isEmpty() && selected.first()->row() != m_shown)
            emit runChosen(selected.first()->row());
    });
    retranslate();
}

void RunsPanel::retranslate()
{
    m_table->setHorizontalHeaderLabels({tr("Run"), tr("Parameters"), tr("Sites"), tr("Vertices"),
                                        tr("Triangles"), tr("Valid"), tr("Hausdorff (% diag.)"),
                                        tr("Mean Q"), tr("Reviewed")});
    m_compare->setText(tr("Compare…"));
    m_compare->setToolTip(tr("Show one run in the input view and another in the output view"));
    m_input->setText(tr("Input vs Output"));
    m_input->setToolTip(tr("Show the input model again beside the run shown"));
}

// Two lists of the runs: by default the run shown goes to the input view, the one before it
// (or after) to the output, for a "before and after" of the last change of parameters.
void RunsPanel::chooseComparison()
{
    const int count = int(m_names.size());
    if (count < 2)
        return;
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Compare Runs"));
    auto *form = new QFormLayout(&dialog);
    auto *first = new QComboBox(&dialog);
    auto *second = new QComboBox(&dialog);
    for (const QString &name : m_names) {
        first->addItem(name);
        second->addItem(name);
    }
    const int shown = m_shown >= 0 ? m_shown : count - 1;
    first->setCurrentIndex(shown > 0 ? shown - 1 : 1);
    second->setCurrentIndex(shown);
    form->addRow(tr("Input view:"), first);
    form->addRow(tr("Output view:"), second);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    const auto check = [&] {
        box->button(QDialogButtonBox::Ok)
            ->setEnabled(first->currentIndex() != second->currentIndex());
    };
    connect(first, &QComboBox::currentIndexChanged, &dialog, check);
    connect(second, &QComboBox::currentIndexChanged, &dialog, check);
    connect(box, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(box);
    check();
    if (dialog.exec() == QDialog::Accepted)
        emit compareChosen(first->currentIndex(), second->currentIndex());
}

void RunsPanel::setRuns(const std::vector<RunsRow> &rows, int shown, int compared)
{
    const QSignalBlocker blocker(m_table);
    m_shown = shown;
    m_compared = compared;
    m_names.clear();
    for (const RunsRow &row : rows)
        m_names.push_back(tr("Run %1: %2").arg(row.id).arg(row.parameters));
    m_compare->setEnabled(rows.size() >= 2);
    m_input->setEnabled(compared >= 0);
    const QLocale locale;
    m_table->setRowCount(int(rows.size()));
    for (int r = 0; r < int(rows.size()); ++r) {
        const RunsRow &row = rows[std::size_t(r)];
        const auto set = [&](int column, const QString &text, bool number = true) {
            auto *item = new QTableWidgetItem(text);
            if (number)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            QFont font = item->font();
            font.setBold(r == shown || r == compared); // the runs in the views
            item->setFont(font);
            m_table->setItem(r, column, item);
        };
        // ◀ the input (left) view, ▶ the output (right) view.
        const QString mark = r == compared ? QStringLiteral("◀ ")
                             : r == shown  ? QStringLiteral("▶ ")
                                           : QString();
        set(Run, mark + QString::number(row.id), false);
        set(Parameters, row.parameters, false);
        set(Sites, locale.toString(row.sites));
        set(Vertices, locale.toString(row.vertices));
        set(Triangles, locale.toString(row.triangles));
        set(Valid, row.valid ? tr("yes") : tr("NO"), false);
        set(Hausdorff, locale.toString(row.hausdorffPctBbox, 'f', 3));
        set(MeanQ, locale.toString(row.meanQuality, 'f', 3));
        set(Reviewed, tr("%1 of %2").arg(row.reviewed).arg(row.records));
    }
    m_table->resizeColumnsToContents();
    m_table->clearSelection();
    if (shown >= 0 && shown < int(rows.size()))
        m_table->selectRow(shown);
}

} // namespace stratamesh
