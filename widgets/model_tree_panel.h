// The Model dock's contents: a search field filtering the tree by name, a Show Box check box and
// the tree of the model's entities (ModelTreeModel) behind a recursive filter.
#pragma once

#include "model_tree_model.h"

#include <QWidget>

class QCheckBox;
class QLineEdit;
class QSortFilterProxyModel;
class QTreeView;

namespace stratamesh {

class ModelTreePanel : public QWidget {
    Q_OBJECT
public:
    explicit ModelTreePanel(QWidget *parent = nullptr);

    ModelTreeModel *treeModel() const { return m_model; }
    QSortFilterProxyModel *proxy() const { return m_proxy; }
    QTreeView *view() const { return m_view; }
    QLineEdit *searchField() const { return m_search; }
    QCheckBox *boxCheck() const { return m_box; }

    // Rebuilds the tree; the filter stays.
    void setModel(std::shared_ptr<const Model> model);
    // Follows the View > Show Box action without echoing it back.
    void setBoxShown(bool shown);
    // Selects and reveals one entity (a picked triangle's surface); the filter is cleared when it
    // hides the row.
    void selectEntity(ModelTreeModel::Kind kind, int entity);
    // The selected row in the source model, or an invalid index.
    QModelIndex selectedIndex() const;
    void retranslate();

signals:
    void boxToggled(bool shown);
    // The current row changed (an invalid index when none is).
    void selected(const QModelIndex &sourceIndex);

protected:
    void changeEvent(QEvent *event) override;

private:
    ModelTreeModel *m_model;
    QSortFilterProxyModel *m_proxy;
    QLineEdit *m_search;
    QCheckBox *m_box;
    QTreeView *m_view;
};

} // namespace stratamesh
