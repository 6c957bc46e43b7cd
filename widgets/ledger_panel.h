// The "Simplifications" panel: the ledger of a remeshing as a table, filtered by kind and by a
// search text, sortable by any column, with a summary line of the counts per kind. Selecting a
// row tells which record to look at.
#pragma once

#include "remesh/simplification_ledger.h"

#include <QWidget>

#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QTableView;

namespace stratamesh {

class LedgerKindFilter;
class LedgerTableModel;

class LedgerPanel : public QWidget {
    Q_OBJECT
public:
    // `model` (adopted) may be a LedgerTableModel with more columns, such as the review's.
    explicit LedgerPanel(QWidget *parent = nullptr, LedgerTableModel *model = nullptr);

    // nullptr clears the table.
    void setLedger(std::shared_ptr<const SimplificationLedger> ledger);
    // Same as choosing in the kind combo; std::nullopt shows every kind.
    void setKindFilter(std::optional<LedgerKind> kind);
    // Same as typing in the search field.
    void setSearchText(const QString &text);
    // Selects the visible row `row` (as a user click would), -1 clears the selection.
    void selectRow(int row);

    int visibleRowCount() const;
    QString summaryText() const;
    LedgerTableModel *tableModel() const { return m_model; }
    LedgerKindFilter *filter() const { return m_filter; }
    QTableView *tableView() const { return m_table; }
    QComboBox *kindCombo() const { return m_kinds; }
    QLineEdit *searchEdit() const { return m_search; }

signals:
    // Index in the ledger of the selected record, -1 when nothing is selected.
    void recordSelected(int recordIndex);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fillKinds();
    void onSelectionChanged();

    LedgerTableModel *m_model;
    LedgerKindFilter *m_filter;
    QComboBox *m_kinds;
    QLabel *m_filterLabel;
    QLineEdit *m_search;
    QLabel *m_summary;
    QTableView *m_table;
};

} // namespace stratamesh
