#include "view_workflow.h"

#include "comparison_table.h"
#include "disabled_reason.h"
#include "error_message.h"
#include "histogram_chart.h"
#include "hybrid_panel.h"
#include "hybrid_workflow.h"
#include "model_scene.h"
#include "remesh_workflow.h"
#include "tetmesh_panel.h"
#include "tetmesh_workflow.h"
#include "workbench.h"

#include "colour_map.h"

#include <QAction>
#include <QActionGroup>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QSlider>
#include <QUndoCommand>
#include <QUndoStack>
#include <QWidgetAction>

#include <vtkLookupTable.h>

#include <algorithm>

namespace stratamesh {

namespace {

constexpr int kSliderSteps = 100;

// Undo restores the colouring chosen before.
class ColourCommand : public QUndoCommand {
public:
    ColourCommand(ViewWorkflow &workflow, const ColourChoice &before, const ColourChoice &after,
                  const QString &text)
        : QUndoCommand(text), m_workflow(workflow), m_before(before), m_after(after)
    {
    }
    void undo() override { apply(m_before); }
    void redo() override { apply(m_after); }

private:
    void apply(const ColourChoice &choice)
    {
        m_workflow.applyColourChoice(choice);
        if (m_before.colouring != m_after.colouring)
            m_workflow.applyTetColouring(choice);
    }

    ViewWorkflow &m_workflow;
    ColourChoice m_before;
    ColourChoice m_after;
};

// Undo restores the plane as it was; a drag of the position slider is one command.
class ClipCommand : public QUndoCommand {
public:
    ClipCommand(ViewWorkflow &workflow, const ClipState &before, const ClipState &after,
                const QString &text)
        : QUndoCommand(text), m_workflow(workflow), m_before(before), m_after(after)
    {
    }
    void undo() override { m_workflow.setClip(m_before.enabled, m_before.axis, m_before.fraction); }
    void redo() override { m_workflow.setClip(m_after.enabled, m_after.axis, m_after.fraction); }
    int id() const override { return isMove() ? 1701 : -1; }
    bool mergeWith(const QUndoCommand *other) override
    {
        const auto *next = static_cast<const ClipCommand *>(other); // same id: a ClipCommand
        if (!next->isMove() || next->m_before != m_after)
            return false;
        m_after = next->m_after;
        return true;
    }

private:
    bool isMove() const
    {
        return m_before.enabled == m_after.enabled && m_before.axis == m_after.axis;
    }

    ViewWorkflow &m_workflow;
    ClipState m_before;
    ClipState m_after;
};

double maxOf(const std::vector<std::vector<double>> &values)
{
    double top = 0.0;
    for (const auto &surface : values)
        for (double v : surface)
            top = std::max(top, v);
    return top;
}

} // namespace

ViewWorkflow::ViewWorkflow(Workbench &bench, RemeshWorkflow &remesh, TetmeshWorkflow &tetmesh,
                           HybridWorkflow &hybrid, QObject *parent)
    : Workflow(bench, parent), m_remesh(remesh), m_tetmesh(tetmesh), m_hybrid(hybrid),
      m_colourMenu(new QMenu(bench.window())), m_colourGroup(new QActionGroup(this)),
      m_reverse(new QAction(this)), m_clipMenu(new QMenu(bench.window())),
      m_clip(new QAction(this)), m_axisGroup(new QActionGroup(this)),
      m_positionAction(new QWidgetAction(this)), m_position(new QSlider(Qt::Horizontal)),
      m_nextWorst(new QAction(this)), m_clearHighlight(new QAction(this)), m_separator(separator())
{
    for (int i = 0; i < 4; ++i) {
        m_colourActions[i] = new QAction(this);
        m_colourActions[i]->setCheckable(true);
        m_colourGroup->addAction(m_colourActions[i]);
        m_colourMenu->addAction(m_colourActions[i]);
        connect(m_colourActions[i], &QAction::triggered, this,
                [this, i] { chooseColouring(Colouring(i)); });
    }
    m_colourActions[0]->setChecked(true);
    m_colourMenu->addSeparator();
    m_reverse->setCheckable(true);
    m_colourMenu->addAction(m_reverse);
    connect(m_reverse, &QAction::triggered, this, &ViewWorkflow::chooseReverse);

    m_clip->setCheckable(true);
    m_clip->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L)); // Ctrl+K is Analyse > Complexity
    connect(m_clip, &QAction::triggered, this,
            [this](bool on) { chooseClip(on, m_axis, m_fraction); });
    m_clipMenu->addAction(m_clip);
    m_clipMenu->addSeparator();
    for (int i = 0; i < 3; ++i) {
        m_axisActions[i] = new QAction(this);
        m_axisActions[i]->setCheckable(true);
        m_axisGroup->addAction(m_axisActions[i]);
        m_clipMenu->addAction(m_axisActions[i]);
        connect(m_axisActions[i], &QAction::triggered, this,
                [this, i] { chooseClip(m_clipEnabled, ClipAxis(i), m_fraction); });
    }
    m_axisActions[int(m_axis)]->setChecked(true);
    m_position->setRange(0, kSliderSteps);
    m_position->setValue(int(m_fraction * kSliderSteps));
    m_position->setObjectName(QStringLiteral("ClipPosition"));
    m_position->setMinimumWidth(160);
    connect(m_position, &QSlider::valueChanged, this,
            [this](int value) { chooseClip(m_clipEnabled, m_axis, double(value) / kSliderSteps); });
    m_positionAction->setDefaultWidget(m_position);
    m_clipMenu->addAction(m_positionAction);

    m_nextWorst->setShortcut(QKeySequence(Qt::Key_BracketRight));
    connect(m_nextWorst, &QAction::triggered, this, &ViewWorkflow::nextWorst);
    m_clearHighlight->setShortcut(QKeySequence(Qt::Key_Escape));
    connect(m_clearHighlight, &QAction::triggered, this, &ViewWorkflow::clearHighlight);
    const auto noModelOrBusy = [this] {
        return !m_bench.model() ? tr("no model open") : tr("another step is running");
    };
    for (QAction *action : m_colourActions)
        if (action != m_colourActions[int(Colouring::Distance)])
            setDisabledReason(action, noModelOrBusy);
    setDisabledReason(m_colourActions[int(Colouring::Distance)], [this] {
        return !m_bench.model() ? tr("no model open")
               : !output()      ? tr("no remeshed model yet")
                                : tr("another step is running");
    });
    setDisabledReason(m_reverse, noModelOrBusy);
    setDisabledReason(m_nextWorst, noModelOrBusy);
    setDisabledReason(m_clip, [] { return tr("no model open"); });
    setDisabledReason(m_clearHighlight, [] { return tr("no model open"); });

    connectCharts();
    // One plane: a change made in the tet meshes' own controls moves it in every view too.
    const auto adopt = [this](bool enabled, ClipAxis axis, double fraction) {
        if (!m_syncing)
            chooseClip(enabled, axis, fraction);
    };
    connect(m_tetmesh.panel(), &TetmeshPanel::clipChanged, this, adopt);
    connect(m_hybrid.panel(), &HybridPanel::clipChanged, this, adopt);
    // A new output: the same colouring and clip on it, a new order of worst triangles.
    connect(&m_remesh, &RemeshWorkflow::finished, this, [this](bool ok) {
        if (!ok)
            return;
        m_inputDistance.clear();
        resetReview();
        applyColourChoice(m_choice);
        applyClip();
        enableActions(m_bench.isBusy());
    });
    enableActions(false);
}

QList<QAction *> ViewWorkflow::menuActions(Menu menu) const
{
    if (menu != Menu::View)
        return {};
    return {m_colourMenu->menuAction(), m_clipMenu->menuAction(), m_nextWorst, m_clearHighlight,
            m_separator};
}

void ViewWorkflow::retranslate()
{
    m_colourMenu->setTitle(tr("&Colour By"));
    m_colourActions[int(Colouring::Entity)]->setText(tr("&Entity"));
    m_colourActions[int(Colouring::MinAngle)]->setText(tr("Triangle &Min Angle"));
    m_colourActions[int(Colouring::Quality)]->setText(tr("Triangle &Quality Q"));
    m_colourActions[int(Colouring::Distance)]->setText(tr("&Distance to the Other Model"));
    m_colourActions[int(Colouring::Distance)]->setStatusTip(
        tr("Colour each vertex by its distance to the other model (needs a remesh)"));
    m_reverse->setText(tr("&Reverse Colours"));
    m_reverse->setStatusTip(tr("Swap the ends of the colour map (bad is yellow by default)"));
    m_clipMenu->setTitle(tr("C&lip Plane"));
    m_clip->setText(tr("&Clip Both Views"));
    m_clip->setStatusTip(tr("Cut the surfaces and the tet meshes of both views with one plane"));
    m_axisActions[0]->setText(tr("Across &X (east)"));
    m_axisActions[1]->setText(tr("Across &Y (north)"));
    m_axisActions[2]->setText(tr("Across &Z (up)"));
    m_position->setToolTip(tr("Position of the clip plane across the models"));
    m_clearHighlight->setText(tr("Clear &Highlight"));
    m_clearHighlight->setStatusTip(
        tr("Remove the highlight of a histogram bar's triangles or of the worst triangle"));
    m_nextWorst->setText(tr("Next &Worst Triangle"));
    m_nextWorst->setStatusTip(
        tr("Fly to the triangles of the output (or the input) by increasing quality Q"));
}

void ViewWorkflow::clear()
{
    m_inputDistance.clear();
    resetReview();
    m_choice = {};
    m_colourActions[0]->setChecked(true);
    m_reverse->setChecked(false);
    m_bench.inputScene()->clearScalarColouring();
    m_bench.outputScene()->clearScalarColouring();
    setClip(false, m_axis, m_fraction);
}

void ViewWorkflow::enableActions(bool busy)
{
    const bool model = m_bench.model() != nullptr;
    for (QAction *action : m_colourActions)
        action->setEnabled(!busy && model);
    m_colourActions[int(Colouring::Distance)]->setEnabled(!busy && output() != nullptr);
    m_reverse->setEnabled(!busy && model);
    m_clip->setEnabled(model);
    m_nextWorst->setEnabled(!busy && model);
    m_clearHighlight->setEnabled(model);
}

std::shared_ptr<const Model> ViewWorkflow::output() const
{
    return m_remesh.outcome() ? m_remesh.outcome()->output : nullptr;
}

QAction *ViewWorkflow::colourAction(Colouring colouring) const
{
    return m_colourActions[int(colouring)];
}

void ViewWorkflow::chooseColouring(Colouring colouring)
{
    ColourChoice after = m_choice;
    after.colouring = colouring;
    if (after == m_choice)
        return;
    m_bench.undoStack()->push(new ColourCommand(
        *this, m_choice, after,
        tr("Colour by %1").arg(colourAction(colouring)->text()).remove(QLatin1Char('&'))));
}

void ViewWorkflow::chooseReverse(bool reverse)
{
    ColourChoice after = m_choice;
    after.reverse = reverse;
    if (after == m_choice)
        return;
    m_bench.undoStack()->push(new ColourCommand(
        *this, m_choice, after, reverse ? tr("Reverse Colours") : tr("Unreverse Colours")));
}

void ViewWorkflow::applyColourChoice(const ColourChoice &choice)
{
    m_choice = choice;
    // What the input view shows: a run when two runs are compared.
    const std::shared_ptr<const Model> input = m_bench.inputScene()->model();
    const std::shared_ptr<const Model> out = output();
    if (m_choice.colouring == Colouring::Distance && !out)
        m_choice.colouring = Colouring::Entity; // nothing to measure against
    colourAction(m_choice.colouring)->setChecked(true);
    m_reverse->setChecked(m_choice.reverse);
    ModelScene *inScene = m_bench.inputScene();
    ModelScene *outScene = m_bench.outputScene();
    if (m_choice.colouring == Colouring::Entity || !input) {
        inScene->clearScalarColouring();
        outScene->clearScalarColouring();
        m_bench.updateLegend();
        m_bench.render();
        return;
    }
    try {
        std::vector<std::vector<double>> inValues, outValues;
        bool perVertex = false;
        bool lowIsBad = true;
        double low = 0.0, high = 1.0;
        QString title;
        switch (m_choice.colouring) {
        case Colouring::MinAngle:
            // Fixed ranges: both views and every remesh compare, as the histograms' bins do.
            high = 60.0;
            title = tr("Min angle (°)");
            inValues = triangleMeasures(*input, TriangleMeasure::MinAngle);
            if (out)
                outValues = triangleMeasures(*out, TriangleMeasure::MinAngle);
            break;
        case Colouring::Quality:
            title = tr("Q");
            inValues = triangleMeasures(*input, TriangleMeasure::Quality);
            if (out)
                outValues = triangleMeasures(*out, TriangleMeasure::Quality);
            break;
        case Colouring::Distance:
            perVertex = true;
            lowIsBad = false;
            title = tr("Distance\n(model units)");
            if (m_inputDistance.empty())
                m_inputDistance = vertexDistances(*input, *out);
            inValues = m_inputDistance;
            outValues = m_remesh.outcome()->comparison.hausdorff.vertexDistanceBToA;
            if (outValues.size() != out->surfaces.size())
                outValues = vertexDistances(*out, *input);
            high = std::max(maxOf(inValues), maxOf(outValues));
            break;
        case Colouring::Entity:
            break;
        }
        const auto table = measureLookupTable(low, high, lowIsBad, m_choice.reverse);
        const std::string name = title.toStdString();
        inScene->setScalarColouring(inValues, perVertex, table, name);
        if (out && outScene->model() == out)
            outScene->setScalarColouring(outValues, perVertex, table, name);
    } catch (const std::exception &e) {
        m_bench.addMessage(errorMessage(e, m_bench.modelPath()));
        m_bench.showMessages();
    }
    m_bench.updateLegend();
    m_bench.render();
}

void ViewWorkflow::chooseClip(bool enabled, ClipAxis axis, double fraction)
{
    const ClipState before{m_clipEnabled, m_axis, m_fraction};
    const ClipState after{enabled, axis, std::clamp(fraction, 0.0, 1.0)};
    if (after == before)
        return;
    const QString text = before.enabled != after.enabled
                             ? (enabled ? tr("Clip Both Views") : tr("Remove the Clip Plane"))
                             : tr("Move the Clip Plane");
    m_bench.undoStack()->push(new ClipCommand(*this, before, after, text));
}

void ViewWorkflow::applyTetColouring(const ColourChoice &choice)
{
    // Tets drawn in place of the surfaces follow: the quality measures colour them by their
    // minimum dihedral angle, the entity colouring by region; a distance leaves them be.
    if (choice.colouring == Colouring::Distance)
        return;
    const TetColouring tets =
        choice.colouring == Colouring::Entity ? TetColouring::Region : TetColouring::MinDihedral;
    m_tetmesh.panel()->setColouring(tets);
    m_hybrid.panel()->setColouring(tets);
}

void ViewWorkflow::setClip(bool enabled, ClipAxis axis, double fraction)
{
    m_clipEnabled = enabled;
    m_axis = axis;
    m_fraction = std::clamp(fraction, 0.0, 1.0);
    m_clip->setChecked(enabled);
    m_axisActions[int(axis)]->setChecked(true);
    {
        const QSignalBlocker block(m_position);
        m_position->setValue(int(std::lround(m_fraction * kSliderSteps)));
    }
    applyClip();
}

void ViewWorkflow::applyClip()
{
    ModelScene *scenes[2] = {m_bench.inputScene(), m_bench.outputScene()};
    double bounds[6], other[6];
    bool any = scenes[0]->bounds(bounds);
    if (scenes[1]->model() && scenes[1]->bounds(other)) {
        if (!any)
            std::copy(other, other + 6, bounds);
        for (int k = 0; k < 3; ++k) {
            bounds[2 * k] = std::min(bounds[2 * k], other[2 * k]);
            bounds[2 * k + 1] = std::max(bounds[2 * k + 1], other[2 * k + 1]);
        }
        any = true;
    }
    if (!m_clipEnabled || !any) {
        for (ModelScene *scene : scenes)
            scene->clearClipPlane();
    } else {
        // The same plane as the tet meshes' (TetMeshPair): the kept side faces the default camera.
        const int k = int(m_axis);
        double origin[3] = {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                            0.5 * (bounds[4] + bounds[5])};
        origin[k] = bounds[2 * k] + m_fraction * (bounds[2 * k + 1] - bounds[2 * k]);
        double normal[3] = {0.0, 0.0, 0.0};
        normal[k] = m_axis == ClipAxis::Z ? 1.0 : -1.0;
        for (ModelScene *scene : scenes)
            scene->setClipPlane(origin, normal);
    }
    // The tet meshes' own clip controls follow, so they show the plane that is drawn.
    m_syncing = true;
    m_tetmesh.panel()->setClip(m_clipEnabled, m_axis, m_fraction);
    m_hybrid.panel()->setClip(m_clipEnabled, m_axis, m_fraction);
    m_syncing = false;
    m_bench.render();
}

void ViewWorkflow::connectCharts()
{
    ComparisonTable *table = m_remesh.comparisonTable();
    connect(table->qualityChart(), &HistogramChart::barClicked, this,
            [this](int bin, bool output) { selectBin(true, bin, output); });
    connect(table->minAngleChart(), &HistogramChart::barClicked, this,
            [this](int bin, bool output) { selectBin(false, bin, output); });
}

int ViewWorkflow::selectBin(bool quality, int bin, bool output)
{
    const ComparisonTable *table = m_remesh.comparisonTable();
    const HistogramChart *chart = quality ? table->qualityChart() : table->minAngleChart();
    const std::optional<Histogram> &histogram =
        output ? chart->outputHistogram() : chart->inputHistogram();
    const auto &outcome = m_remesh.outcome();
    const std::shared_ptr<const Model> model =
        !outcome ? nullptr : (output ? outcome->output : outcome->input);
    ModelScene *scene = output ? m_bench.outputScene() : m_bench.inputScene();
    ModelScene *otherScene = output ? m_bench.inputScene() : m_bench.outputScene();
    otherScene->clearHighlight();
    m_selectionCount = 0;
    if (!histogram || !model || bin < 0 || std::size_t(bin) >= histogram->binCount()
        || scene->model() != model) {
        scene->clearHighlight();
        m_bench.render();
        return 0;
    }
    const TriangleMeasure measure = quality ? TriangleMeasure::Quality : TriangleMeasure::MinAngle;
    std::vector<std::pair<int, int>> triangles;
    try {
        for (const MeasuredTriangle &t : trianglesInBin(*model, measure, *histogram, bin))
            triangles.emplace_back(t.surface, t.triangle);
    } catch (const std::exception &e) {
        m_bench.addMessage(errorMessage(e, m_bench.modelPath()));
    }
    scene->setHighlight(triangles);
    m_selectionCount = scene->highlightCount();
    const std::size_t expected = histogram->counts()[std::size_t(bin)];
    if (std::size_t(m_selectionCount) != expected) {
        // Never silently: the bar and the highlight would disagree.
        Message mismatch;
        mismatch.severity = Message::Severity::Warning;
        mismatch.text = tr("%1 triangles highlighted for a bar of %2")
                            .arg(m_selectionCount)
                            .arg(qulonglong(expected));
        m_bench.addMessage(mismatch);
    }
    const QLocale locale;
    const int decimals = quality ? 2 : 0;
    const QString what = quality ? tr("Q") : tr("min angle");
    const QString low = locale.toString(histogram->edges()[std::size_t(bin)], 'f', decimals);
    const QString high = locale.toString(histogram->edges()[std::size_t(bin) + 1], 'f', decimals);
    // Whole sentences for each side: the article differs in French.
    m_bench.setStatus((output ? tr("%n triangle(s) of the output highlighted: %1 in [%2, %3]",
                                   nullptr, m_selectionCount)
                              : tr("%n triangle(s) of the input highlighted: %1 in [%2, %3]",
                                   nullptr, m_selectionCount))
                          .arg(what, low, high));
    m_bench.render();
    return m_selectionCount;
}

void ViewWorkflow::clearHighlight()
{
    m_bench.inputScene()->clearHighlight();
    m_bench.outputScene()->clearHighlight();
    m_selectionCount = 0;
    m_bench.hidePosition();
}

void ViewWorkflow::resetReview()
{
    m_worst.clear();
    m_worstNext = 0;
    m_selectionCount = 0;
}

void ViewWorkflow::nextWorst()
{
    const std::shared_ptr<const Model> out = output();
    const std::shared_ptr<const Model> model = out ? out : m_bench.model();
    ModelScene *scene = out ? m_bench.outputScene() : m_bench.inputScene();
    if (!model)
        return;
    // The box's triangles only while the box is shown: a hidden triangle shows nothing.
    const bool withBox = scene->boxVisible();
    if (m_worst.empty() || m_worstOfOutput != bool(out) || m_worstWithBox != withBox) {
        try {
            m_worst = trianglesByMeasure(*model, TriangleMeasure::Quality);
        } catch (const std::exception &e) {
            m_bench.addMessage(errorMessage(e, m_bench.modelPath()));
            m_bench.showMessages();
            return;
        }
        if (!withBox)
            m_worst.erase(std::remove_if(m_worst.begin(), m_worst.end(),
                                         [&](const MeasuredTriangle &t) {
                                             return model->surfaces[std::size_t(t.surface)].type
                                                    == FeatureType::Boundary;
                                         }),
                          m_worst.end());
        m_worstOfOutput = bool(out);
        m_worstWithBox = withBox;
        m_worstNext = 0;
    }
    if (m_worst.empty())
        return;
    if (m_worstNext >= int(m_worst.size()))
        m_worstNext = 0; // round again from the worst
    const MeasuredTriangle &t = m_worst[std::size_t(m_worstNext++)];
    (out ? m_bench.inputScene() : m_bench.outputScene())->clearHighlight();
    scene->setHighlight({{t.surface, t.triangle}});
    m_selectionCount = 1;
    m_bench.showPosition(t.centroid);
    const QLocale locale;
    const QString text =
        out ? tr("Worst triangle %1 of the output: surface %2, triangle %3, Q = %4")
            : tr("Worst triangle %1 of the input: surface %2, triangle %3, Q = %4");
    m_bench.setStatus(text.arg(locale.toString(m_worstNext),
                               QString::fromStdString(model->surfaces[std::size_t(t.surface)].name),
                               locale.toString(t.triangle), locale.toString(t.value, 'f', 3)));
}

std::optional<MeasuredTriangle> ViewWorkflow::lastWorst() const
{
    if (m_worstNext <= 0 || m_worstNext > int(m_worst.size()))
        return std::nullopt;
    return m_worst[std::size_t(m_worstNext - 1)];
}

} // namespace stratamesh
