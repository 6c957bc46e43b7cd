#include "model_tree_panel.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QVBoxLayout>

namespace stratamesh {

ModelTreePanel::ModelTreePanel(QWidget *parent)
    : QWidget(parent), m_model(new ModelTreeModel(this)), m_proxy(new QSortFilterProxyModel(this)),
      m_search(new QLineEdit(this)), m_box(new QCheckBox(this)), m_view(new QTreeView(this))
{
    setObjectName(QStringLiteral("ModelTreePanel"));
    // A surface matching the search shows with the groups above it; groups match on nothing of
    // their own, so "fault" lists fault surfaces, not every row under "Faults".
    m_proxy->setSourceModel(m_model);
    m_proxy->setRecursiveFilteringEnabled(true);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterRole(ModelTreeModel::NameRole);
    m_search->setClearButtonEnabled(true);
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_proxy->setFilterFixedString(text);
        if (!text.isEmpty())
            m_view->expandAll();
    });

    m_view->setModel(m_proxy);
    m_view->setHeaderHidden(true);
    m_view->setUniformRowHeights(true);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) { emit selected(m_proxy->mapToSource(current)); });
    connect(m_box, &QCheckBox::toggled, this, &ModelTreePanel::boxToggled);

    auto *top = new QHBoxLayout;
    top->addWidget(m_search, 1);
    top->addWidget(m_box);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addWidget(m_view, 1);
    retranslate();
}

void ModelTreePanel::setModel(std::shared_ptr<const Model> model)
{
    m_model->setModel(std::move(model));
    // The top groups open, the long lists of lines and corners closed.
    for (int row = 0; row < m_proxy->rowCount(); ++row) {
        const QModelIndex group = m_proxy->index(row, 0);
        if (!group.data().toString().startsWith(tr("Lines"))
            && !group.data().toString().startsWith(tr("Corners")))
            m_view->expand(group);
    }
}

void ModelTreePanel::setBoxShown(bool shown)
{
    const QSignalBlocker block(m_box);
    m_box->setChecked(shown);
    m_model->setBoxShown(shown);
}

void ModelTreePanel::selectEntity(ModelTreeModel::Kind kind, int entity)
{
    const QModelIndex source = m_model->indexOf(kind, entity);
    if (!source.isValid())
        return;
    QModelIndex shown = m_proxy->mapFromSource(source);
    if (!shown.isValid()) {
        m_search->clear();
        shown = m_proxy->mapFromSource(source);
    }
    m_view->scrollTo(shown);
    m_view->selectionModel()->setCurrentIndex(shown, QItemSelectionModel::ClearAndSelect);
}

QModelIndex ModelTreePanel::selectedIndex() const
{
    return m_proxy->mapToSource(m_view->selectionModel()->currentIndex());
}

void ModelTreePanel::retranslate()
{
    m_search->setPlaceholderText(tr("Filter by name"));
    m_box->setText(tr("Show box"));
    m_box->setToolTip(tr("Show the surfaces of the model's bounding box"));
    m_model->retranslate();
}

void ModelTreePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace stratamesh
