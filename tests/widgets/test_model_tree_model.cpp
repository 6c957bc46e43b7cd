// The Model dock's tree over the scene test model: groups and counts, tri-state check boxes, the
// request-then-apply visibility protocol and the recursive search by name.
#include "scene_test_model.h"

#include "model_tree_model.h"
#include "model_tree_panel.h"

#include <QApplication>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QtTest>

using namespace stratamesh;
using Kind = ModelTreeModel::Kind;

namespace {

// Rows below `parent` of the proxy (all levels) that stand for an entity.
QStringList entityRows(const QAbstractItemModel &m, const QModelIndex &parent = {})
{
    QStringList names;
    for (int r = 0; r < m.rowCount(parent); ++r) {
        const QModelIndex i = m.index(r, 0, parent);
        if (Kind(i.data(ModelTreeModel::KindRole).toInt()) != Kind::Group)
            names.append(i.data(ModelTreeModel::NameRole).toString());
        names.append(entityRows(m, i));
    }
    return names;
}

QModelIndex topGroup(const QAbstractItemModel &m, const QString &prefix)
{
    for (int r = 0; r < m.rowCount(); ++r)
        if (m.index(r, 0).data().toString().startsWith(prefix))
            return m.index(r, 0);
    return {};
}

} // namespace

class TestModelTreeModel : public QObject {
    Q_OBJECT
private slots:
    void countsAreTheTopologys()
    {
        auto model = std::make_shared<const Model>(test::sceneTestModel());
        ModelTreeModel tree;
        tree.setModel(model);
        QCOMPARE(tree.entityCount(Kind::Surface), int(model->surfaces.size()));
        QCOMPARE(tree.entityCount(Kind::Line), int(model->lines.size()));
        QCOMPARE(tree.entityCount(Kind::Corner), int(model->corners.size()));
        QVERIFY(model->lines.size() > 4);
        QCOMPARE(tree.rowCount(), 4); // Regions, Surfaces, Lines, Corners
        const QModelIndex surfaces = topGroup(tree, QStringLiteral("Surfaces"));
        QVERIFY(surfaces.isValid());
        QCOMPARE(surfaces.data().toString(), QStringLiteral("Surfaces (8)"));
        QCOMPARE(tree.rowCount(surfaces), 3); // Horizons, Faults, Box
        QCOMPARE(tree.index(2, 0, surfaces).data().toString(), QStringLiteral("Box (6)"));
        QCOMPARE(entityRows(tree).size(),
                 int(model->surfaces.size() + model->lines.size() + model->corners.size()));
        // Every entity row comes back to its own index through parent().
        const QModelIndex fault = tree.indexOf(Kind::Surface, 1);
        QCOMPARE(fault.data(ModelTreeModel::NameRole).toString(), QStringLiteral("fault"));
        QCOMPARE(tree.index(fault.row(), 0, tree.parent(fault)), fault);
        QVERIFY(tree.describe(fault).contains(QStringLiteral("32 triangle")));
        QVERIFY(tree.describe(tree.indexOf(Kind::Line, 0)).contains(QStringLiteral("length")));
    }

    void checkingAsksThenApplies()
    {
        auto model = std::make_shared<const Model>(test::sceneTestModel());
        ModelTreeModel tree;
        tree.setModel(model);
        QSignalSpy requests(&tree, &ModelTreeModel::visibilityRequested);
        const QModelIndex fault = tree.indexOf(Kind::Surface, 1);
        QCOMPARE(fault.data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
        QVERIFY(tree.setData(fault, Qt::Unchecked, Qt::CheckStateRole));
        QCOMPARE(requests.size(), 1);
        QCOMPARE(requests[0][0].value<QList<int>>(), QList<int>{1});
        QCOMPARE(requests[0][1].toBool(), false);
        // Nothing changes until the caller applies it (as its undo command does).
        QVERIFY(tree.surfaceVisible(1));
        tree.setSurfacesVisible({1}, false);
        QCOMPARE(fault.data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        const QModelIndex surfaces = topGroup(tree, QStringLiteral("Surfaces"));
        QCOMPARE(surfaces.data(Qt::CheckStateRole).toInt(), int(Qt::PartiallyChecked));
        // A group's check asks for exactly the surfaces that change.
        const QModelIndex box = tree.index(2, 0, surfaces);
        QVERIFY(tree.setData(surfaces, Qt::Unchecked, Qt::CheckStateRole));
        QCOMPARE(requests.size(), 2);
        QCOMPARE(requests[1][0].value<QList<int>>().size(), 7);
        tree.setSurfacesVisible({2, 3, 4, 5, 6, 7}, false);
        QCOMPARE(box.data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        QCOMPARE(surfaces.data(Qt::CheckStateRole).toInt(), int(Qt::PartiallyChecked));
        // Lines and corners carry no check box.
        QVERIFY(!tree.indexOf(Kind::Line, 0).data(Qt::CheckStateRole).isValid());
        QVERIFY(!(tree.flags(tree.indexOf(Kind::Corner, 0)) & Qt::ItemIsUserCheckable));
    }

    void searchKeepsMatchingRows()
    {
        ModelTreePanel panel;
        panel.setModel(std::make_shared<const Model>(test::sceneTestModel()));
        panel.searchField()->setText(QStringLiteral("FAU"));
        QCOMPARE(entityRows(*panel.proxy()), QStringList{QStringLiteral("fault")});
        panel.searchField()->setText(QStringLiteral("line_1"));
        const QStringList lines = entityRows(*panel.proxy());
        QVERIFY(!lines.isEmpty());
        for (const QString &name : lines)
            QVERIFY2(name.startsWith(QStringLiteral("line_1")), qPrintable(name));
        // Selecting a row the filter hides clears the filter.
        panel.selectEntity(Kind::Surface, 0);
        QVERIFY(panel.searchField()->text().isEmpty());
        QCOMPARE(panel.selectedIndex(), panel.treeModel()->indexOf(Kind::Surface, 0));
    }
};

QTEST_MAIN(TestModelTreeModel)
#include "test_model_tree_model.moc"
