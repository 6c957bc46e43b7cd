// The Model dock on modelA1: the tree lists the topology's entities, a check box hides a surface
// in the view and Edit > Undo brings it back, the search keeps matching rows, the dock's box
// toggle and View > Show Box agree, a selected surface is overlaid with its own triangles, a
// click on a triangle in the view names its surface in the status bar, and the pointer resting on
// it names it in a tooltip.
#include "support/test_data.h"

#include "entity_highlight.h"
#include "main_window.h"
#include "model/model_counts.h"
#include "model_scene.h"
#include "model_tree_panel.h"
#include "model_tree_workflow.h"
#include "open_workflow.h"
#include "position_marker.h"
#include "progress_strip.h"
#include "remesh_workflow.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QSurfaceFormat>
#include <QToolTip>
#include <QTreeView>
#include <QUndoStack>
#include <QtTest>

#include <vtkActor.h>
#include <vtkRenderer.h>

using namespace stratamesh;
using Kind = ModelTreeModel::Kind;

namespace {

constexpr int kLoadTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);

bool load(MainWindow &window, const QString &path)
{
    QSignalSpy finished(window.openWorkflow(), &OpenWorkflow::finished);
    window.openFile(path);
    if (!finished.wait(kLoadTimeoutMs))
        return false;
    return finished.first().first().toBool();
}

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

int surfaceNamed(const Model &model, const std::string &name)
{
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        if (model.surfaces[s].name == name)
            return int(s);
    return -1;
}

// Counts the pointer events the window system itself delivers to a widget (not those a test
// sends): they move the pointer, and so may start a hover, whatever the test does.
class WindowSystemPointer : public QObject {
public:
    explicit WindowSystemPointer(QWidget *widget) { widget->installEventFilter(this); }
    int events() const { return m_events; }

protected:
    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->spontaneous()
            && (event->type() == QEvent::MouseMove || event->type() == QEvent::Enter))
            ++m_events;
        return false;
    }

private:
    int m_events = 0;
};

} // namespace

class TestGuiModelTree : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QVERIFY(load(*m_window, path));
        m_tree = m_window->modelTreeWorkflow();
        QVERIFY(m_tree);
        m_panel = m_tree->panel();
        m_model = m_window->scene()->model();
        QVERIFY(m_model);
    }

    void cleanupTestCase() { m_window.reset(); }

    void treeCountsAreTheModels()
    {
        QVERIFY(m_tree->dock()->isVisible());
        const ModelCounts counts = countEntities(*m_model);
        const ModelTreeModel *tree = m_panel->treeModel();
        QCOMPARE(tree->entityCount(Kind::Surface), counts.all.surfaces);
        QCOMPARE(tree->entityCount(Kind::Line), counts.all.lines);
        QCOMPARE(tree->entityCount(Kind::Corner), counts.all.corners);
        QCOMPARE(tree->entityCount(Kind::Region), counts.all.regions);
        QCOMPARE(entityRows(*m_panel->proxy()).size(),
                 counts.all.regions + counts.all.surfaces + counts.all.lines + counts.all.corners);
        qInfo("tree: %d regions, %d surfaces, %d lines, %d corners", counts.all.regions,
              counts.all.surfaces, counts.all.lines, counts.all.corners);
    }

    void uncheckHidesAndUndoShows()
    {
        const int s = surfaceNamed(*m_model, "h2_model1");
        QVERIFY(s >= 0);
        vtkActor *actor = m_window->scene()->surfaceActor(s);
        QVERIFY(actor->GetVisibility());
        QUndoStack *undo = m_window->workbench()->undoStack();
        const int before = undo->count();
        // As the view does on a click in the check box.
        const QModelIndex row =
            m_panel->proxy()->mapFromSource(m_panel->treeModel()->indexOf(Kind::Surface, s));
        QVERIFY(m_panel->proxy()->setData(row, Qt::Unchecked, Qt::CheckStateRole));
        QCOMPARE(undo->count(), before + 1);
        QVERIFY(!actor->GetVisibility());
        QCOMPARE(row.data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        QCOMPARE(undo->undoText(), QStringLiteral("Hide h2_model1"));
        undo->undo();
        QVERIFY(actor->GetVisibility());
        QCOMPARE(row.data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
        // The box toggle does not bring back a surface the user hid.
        undo->redo();
        m_window->showBoxAction()->trigger();
        m_window->showBoxAction()->trigger();
        QVERIFY(!actor->GetVisibility());
        undo->undo();
        QVERIFY(actor->GetVisibility());
    }

    void searchKeepsMatchingRows()
    {
        const int all = entityRows(*m_panel->proxy()).size();
        m_panel->searchField()->setText(QStringLiteral("h2_"));
        const QStringList rows = entityRows(*m_panel->proxy());
        QVERIFY(!rows.isEmpty());
        QVERIFY(rows.size() < all);
        for (const QString &name : rows)
            QVERIFY2(name.contains(QStringLiteral("h2_")), qPrintable(name));
        m_panel->searchField()->clear();
        QCOMPARE(entityRows(*m_panel->proxy()).size(), all);
    }

    void boxToggleAgreesWithTheViewMenu()
    {
        QAction *showBox = m_window->showBoxAction();
        QCheckBox *check = m_panel->boxCheck();
        QVERIFY(!showBox->isChecked());
        QVERIFY(!check->isChecked());
        check->click();
        QVERIFY(showBox->isChecked());
        QVERIFY(m_window->scene()->boxVisible());
        showBox->trigger();
        QVERIFY(!check->isChecked());
        QVERIFY(!m_window->scene()->boxVisible());
        showBox->trigger();
        QVERIFY(check->isChecked());
        check->click();
        QVERIFY(!showBox->isChecked());
    }

    void selectionHighlights()
    {
        const int s = surfaceNamed(*m_model, "h1_model1");
        QVERIFY(s >= 0);
        m_panel->selectEntity(Kind::Surface, s);
        QCOMPARE(m_tree->inputHighlight()->triangleCount(),
                 int(m_model->surfaces[std::size_t(s)].triangles.size()));
        const QString status = m_window->progressStrip()->text();
        QVERIFY2(status.contains(QStringLiteral("h1_model1")), qPrintable(status));
        QVERIFY2(status.contains(QStringLiteral("triangles")), qPrintable(status));

        const Line &line = m_model->lines.front();
        m_panel->selectEntity(Kind::Line, 0);
        QCOMPARE(m_tree->inputHighlight()->triangleCount(), 0);
        QCOMPARE(m_tree->inputHighlight()->segmentCount(),
                 int(line.vertices.size()) - 1 + (line.closed ? 1 : 0));
        QVERIFY(m_window->progressStrip()->text().contains(QStringLiteral("length")));

        m_panel->selectEntity(Kind::Corner, 0);
        QVERIFY(m_tree->inputHighlight()->cornerMarker().isVisible());
        const Vec3 corner = m_model->vertices[std::size_t(m_model->corners[0].vertex)];
        QVERIFY((m_tree->inputHighlight()->cornerMarker().position() - corner).norm() < 1e-9);
    }

    void clickNamesTheTriangle()
    {
        // Only one horizon shown, so no other surface lies in front of the triangle.
        const int s = surfaceNamed(*m_model, "h2_model1");
        QVERIFY(s >= 0);
        QList<int> others;
        for (int i = 0; i < int(m_model->surfaces.size()); ++i)
            if (i != s)
                others.append(i);
        m_tree->applySurfacesVisible(others, false);
        const Surface &surface = m_model->surfaces[std::size_t(s)];
        const Triangle &t = surface.triangles[surface.triangles.size() / 2];
        const Vec3 centroid =
            (surface.vertices[std::size_t(t[0])] + surface.vertices[std::size_t(t[1])]
             + surface.vertices[std::size_t(t[2])])
            / 3.0;
        VtkViewWidget *view = m_window->view();
        view->grabFramebuffer(); // the camera's clipping range is set by a render
        vtkRenderer *renderer = view->renderer();
        renderer->SetWorldPoint(centroid.x(), centroid.y(), centroid.z(), 1.0);
        renderer->WorldToDisplay();
        double d[3];
        renderer->GetDisplayPoint(d);
        const qreal ratio = view->devicePixelRatioF();
        const QPoint at(int(std::lround(d[0] / ratio)),
                        int(std::lround((view->height() * ratio - 1.0 - d[1]) / ratio)));
        QVERIFY2(view->rect().contains(at),
                 qPrintable(QStringLiteral("%1,%2").arg(at.x()).arg(at.y())));
        QSignalSpy clicked(view, &VtkViewWidget::clicked);
        m_panel->selectEntity(Kind::Line, 0);
        QTest::mouseClick(view, Qt::LeftButton, {}, at);
        QCOMPARE(clicked.size(), 1);
        const QString status = m_window->progressStrip()->text();
        qInfo("%s", qPrintable(status));
        QVERIFY2(status.startsWith(QStringLiteral("Surface h2_model1, triangle ")),
                 qPrintable(status));
        QVERIFY(status.contains(QStringLiteral("Q = ")));
        QCOMPARE(m_panel->selectedIndex(), m_panel->treeModel()->indexOf(Kind::Surface, s));
        // A click beside the model finds nothing and leaves the status.
        QTest::mouseClick(view, Qt::LeftButton, {}, QPoint(3, 3));
        QCOMPARE(m_window->progressStrip()->text(), status);
        m_tree->applySurfacesVisible(others, true);
    }

    // After a remesh the output, matched by surface name, follows the tree's choices.
    void outputFollowsTheTree()
    {
        const int s = surfaceNamed(*m_model, "h2_model1");
        const QModelIndex row =
            m_panel->proxy()->mapFromSource(m_panel->treeModel()->indexOf(Kind::Surface, s));
        QVERIFY(m_panel->proxy()->setData(row, Qt::Unchecked, Qt::CheckStateRole));
        m_panel->selectEntity(Kind::Surface, surfaceNamed(*m_model, "h1_model1"));
        RemeshParams params;
        params.sites = 300;
        params.iterations = 20;
        QSignalSpy finished(m_window->remeshWorkflow(), &RemeshWorkflow::finished);
        QElapsedTimer timer;
        timer.start();
        QVERIFY(m_window->remeshWorkflow()->start(params));
        QVERIFY(finished.wait(kLoadTimeoutMs));
        QVERIFY(finished.first().first().toBool());
        qInfo("remesh: %lld ms", timer.elapsed());
        const auto &output = m_window->outputScene()->model();
        QVERIFY(output);
        const int hidden = surfaceNamed(*output, "h2_model1");
        const int selected = surfaceNamed(*output, "h1_model1");
        QVERIFY(hidden >= 0 && selected >= 0);
        QVERIFY(!m_window->outputScene()->surfaceActor(hidden)->GetVisibility());
        QVERIFY(m_window->outputScene()->surfaceActor(selected)->GetVisibility());
        // The selection made before the remesh is drawn on the new output.
        QCOMPARE(m_tree->outputHighlight()->triangleCount(),
                 int(output->surfaces[std::size_t(selected)].triangles.size()));
        m_window->workbench()->undoStack()->undo();
        QVERIFY(m_window->outputScene()->surfaceActor(hidden)->GetVisibility());
        m_panel->selectEntity(Kind::Surface, s);
        QCOMPARE(m_tree->outputHighlight()->triangleCount(),
                 int(output->surfaces[std::size_t(hidden)].triangles.size()));
        QVERIFY(m_tree->outputHighlight()->triangleCount()
                != int(m_model->surfaces[std::size_t(s)].triangles.size()));

        // A click in the output view names the output triangle and selects its input surface.
        m_panel->selectEntity(Kind::Line, 0);
        QVERIFY(m_tree->inspect(true, 0, 0) == false);
        const Surface &surface = output->surfaces[std::size_t(hidden)];
        for (int i = 0; i < int(output->surfaces.size()); ++i)
            if (i != hidden)
                m_window->outputScene()->setSurfaceVisible(i, false);
        const Triangle &t = surface.triangles[surface.triangles.size() / 2];
        const Vec3 centroid =
            (surface.vertices[std::size_t(t[0])] + surface.vertices[std::size_t(t[1])]
             + surface.vertices[std::size_t(t[2])])
            / 3.0;
        VtkViewWidget *view = m_window->outputView();
        view->grabFramebuffer();
        vtkRenderer *renderer = view->renderer();
        renderer->SetWorldPoint(centroid.x(), centroid.y(), centroid.z(), 1.0);
        renderer->WorldToDisplay();
        double d[3];
        renderer->GetDisplayPoint(d);
        QVERIFY(m_tree->inspect(true, d[0], d[1]));
        const QString status = m_window->progressStrip()->text();
        qInfo("%s", qPrintable(status));
        QVERIFY2(status.startsWith(QStringLiteral("Output surface h2_model1, triangle ")),
                 qPrintable(status));
        QCOMPARE(m_panel->selectedIndex(), m_panel->treeModel()->indexOf(Kind::Surface, s));

        // The pointer resting on the same spot describes the triangle in a tooltip, selecting
        // nothing; any move or button press takes the tooltip away.
        m_panel->selectEntity(Kind::Line, 0);
        const QModelIndex line = m_panel->selectedIndex();
        const qreal ratio = view->devicePixelRatioF();
        const QPointF local(d[0] / ratio, (view->height() * ratio - d[1] - 1.0) / ratio);
        QSignalSpy hovered(view, &VtkViewWidget::hovered);
        QMouseEvent move(QEvent::MouseMove, local, view->mapToGlobal(local), Qt::NoButton,
                         Qt::NoButton, Qt::NoModifier);
        // A window-system Leave delivered during a wait stops the rest timer (seen under load):
        // the pointer is moved again then, at most three times.
        auto rest = [&] {
            for (int attempt = 0; attempt < 3; ++attempt) {
                QApplication::sendEvent(view, &move);
                if (attempt == 0 && hovered.count() != 0)
                    return false; // not on every move: the pointer must rest first
                if (hovered.wait(5 * VtkViewWidget::kHoverDelayMs))
                    return true;
            }
            return false;
        };
        QVERIFY(rest());
        QTRY_VERIFY(QToolTip::isVisible());
        qInfo("tooltip: %s", qPrintable(QToolTip::text()));
        QVERIFY2(QToolTip::text().startsWith(QStringLiteral("Output surface h2_model1, triangle ")),
                 qPrintable(QToolTip::text()));
        QCOMPARE(QToolTip::text(), status);
        QCOMPARE(m_panel->selectedIndex(), line);
        QVERIFY(m_tree->hover(true, 1.0, 1.0).isEmpty()); // the corner of the view: no surface
        QTRY_VERIFY(!QToolTip::isVisible());
        QCOMPARE(m_tree->hover(true, d[0], d[1]), status);
        QTRY_VERIFY(QToolTip::isVisible());
        // Leaving the view ends the hover. The pointer rests once more right before the Leave:
        // the event loop run by the waits above may deliver the window system's own pointer
        // events (a slow, sanitized build showed that), which end a hover too.
        QSignalSpy ended(view, &VtkViewWidget::hoverEnded);
        hovered.clear();
        QVERIFY(rest());
        const int rests = int(hovered.count());
        ended.clear();
        const WindowSystemPointer pointer(view);
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(view, &leave);
        QCOMPARE(ended.count(), 1);
        QTRY_VERIFY(!QToolTip::isVisible());
        QTest::qWait(2 * VtkViewWidget::kHoverDelayMs);
        // Gone from the view, the pointer describes nothing, unless the window system moved it
        // back in meanwhile.
        if (pointer.events() == 0)
            QCOMPARE(int(hovered.count()), rests);
        else
            qInfo("%d pointer events from the window system after the leave", pointer.events());

        m_tree->applySurfacesVisible({}, true); // the output follows the tree again
        for (int i = 0; i < int(output->surfaces.size()); ++i)
            QVERIFY(m_window->outputScene()->surfaceActor(i)->GetVisibility()
                    || output->surfaces[std::size_t(i)].type == FeatureType::Boundary);
    }

    void screenshotShowsTreeAndHighlight()
    {
        const int s = surfaceNamed(*m_model, "h2_model1");
        m_panel->view()->collapseAll();
        m_panel->selectEntity(Kind::Line, 0);
        m_panel->view()->collapseAll();
        m_panel->selectEntity(Kind::Surface, s);
        QVERIFY(m_tree->inputHighlight()->surfaceOverlay()->GetVisibility());
        QDir().mkpath(kShots);
        const QString file = kShots + QStringLiteral("/model_tree.png");
        QVERIFY(saveWindowScreenshot(m_window.get(), file));
        qInfo("screenshot: %s", qPrintable(file));
    }

private:
    std::unique_ptr<MainWindow> m_window;
    ModelTreeWorkflow *m_tree = nullptr;
    ModelTreePanel *m_panel = nullptr;
    std::shared_ptr<const Model> m_model;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiModelTree test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_model_tree.moc"
