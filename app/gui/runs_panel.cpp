#include "runs_panel.h"

#include <QHeaderView>
#include <QLocale>
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

RunsPanel::RunsPanel(QWidget *parent) : QWidget(parent), m_table(new QTableWidget(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
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
}

void RunsPanel::setRuns(const std::vector<RunsRow> &rows, int shown)
{
    const QSignalBlocker blocker(m_table);
    m_shown = shown;
    const QLocale locale;
    m_table->setRowCount(int(rows.size()));
    for (int r = 0; r < int(rows.size()); ++r) {
        const RunsRow &row = rows[std::size_t(r)];
        const auto set = [&](int column, const QString &text, bool number = true) {
            auto *item = new QTableWidgetItem(text);
            if (number)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            QFont font = item->font();
            font.setBold(r == shown); // the run in the output view
            item->setFont(font);
            m_table->setItem(r, column, item);
        };
        set(Run, (r == shown ? QStringLiteral("▶ ") : QString()) + QString::number(row.id), false);
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
