#include "model_scene.h"

#include "feature_palette.h"

#include <vtkActor.h>
#include <vtkBoundingBox.h>
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <cmath>
#include <map>

namespace stratamesh {

namespace {

void setColor(vtkProperty *property, const QColor &c)
{
    property->SetColor(c.redF(), c.greenF(), c.blueF());
}

vtkSmartPointer<vtkActor> makeActor(vtkPolyData *data)
{
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

vtkSmartPointer<vtkPolyData> surfacePolyData(const Surface &surface)
{
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble(); // Gocad coordinates (~1e6) lose digits in float
    points->SetNumberOfPoints(vtkIdType(surface.vertices.size()));
    for (std::size_t i = 0; i < surface.vertices.size(); ++i)
        points->SetPoint(vtkIdType(i), surface.vertices[i].data());
    vtkNew<vtkCellArray> triangles;
    const int n = int(surface.vertices.size());
    for (const Triangle &t : surface.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= n || t[1] >= n || t[2] >= n)
            continue; // never trust indices enough to crash the viewer
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        triangles->InsertNextCell(3, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(triangles);
    return data;
}

vtkSmartPointer<vtkPoints> modelPoints(const Model &model)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(model.vertices.size()));
    for (std::size_t i = 0; i < model.vertices.size(); ++i)
        points->SetPoint(vtkIdType(i), model.vertices[i].data());
    return points;
}

bool validVertex(const Model &model, int v)
{
    return v >= 0 && std::size_t(v) < model.vertices.size();
}

} // namespace

ModelScene::ModelScene(vtkRenderer *renderer) : m_renderer(renderer)
{
    // Lines and corners lie exactly on surfaces: push polygons back so they stay visible.
    vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
}

ModelScene::~ModelScene()
{
    clear();
    clearExtras();
}

void ModelScene::setModel(std::shared_ptr<const Model> model)
{
    clear();
    m_model = std::move(model);
    if (!m_model)
        return;
    buildSurfaces();
    buildLinesAndCorners();
    buildLegend();
    applyVisibility();
    applyClip();
}

void ModelScene::clear()
{
    for (auto &actor : m_surfaceActors)
        m_renderer->RemoveActor(actor);
    for (auto *actor : {&m_lines, &m_boxLines, &m_corners, &m_boxCorners}) {
        if (*actor)
            m_renderer->RemoveActor(*actor);
        *actor = nullptr;
    }
    m_surfaceActors.clear();
    m_isBoxSurface.clear();
    m_surfaceShown.clear();
    m_surfaceColors.clear();
    m_legend.clear();
    m_lineCount = 0;
    m_cornerCount = 0;
    m_model.reset();
    clearExtras();
}

void ModelScene::buildSurfaces()
{
    const Model &model = *m_model;
    // Features are numbered per type in order of first appearance; surfaces per feature.
    std::map<FeatureType, std::map<std::string, int>> featureIndex;
    std::map<std::string, int> surfacesSeen;
    for (const Surface &surface : model.surfaces) {
        auto &features = featureIndex[surface.type];
        const auto it = features.emplace(surface.featureName, int(features.size())).first;
        const int surfaceIndex =
            surfacesSeen[featureTypeName(surface.type) + "/" + surface.featureName]++;
        const QColor color = featureColor(surface.type, it->second, surfaceIndex);
        const bool isBox = surface.type == FeatureType::Boundary;

        auto data = surfacePolyData(surface);
        auto actor = makeActor(data);
        vtkProperty *p = actor->GetProperty();
        setColor(p, color);
        p->SetAmbient(0.22); // steep faults facing away from the key light stay readable
        p->SetDiffuse(0.8);
        p->SetSpecular(isBox ? 0.0 : 0.18);
        p->SetSpecularPower(30.0);
        p->SetEdgeColor(color.darker(180).redF(), color.darker(180).greenF(),
                        color.darker(180).blueF());
        if (isBox)
            p->SetOpacity(0.18);
        m_renderer->AddActor(actor);
        m_surfaceActors.push_back(actor);
        m_isBoxSurface.push_back(isBox);
        m_surfaceShown.push_back(true);
        m_surfaceColors.push_back(color);
    }
}

void ModelScene::buildLinesAndCorners()
{
    const Model &model = *m_model;
    if (model.vertices.empty())
        return;
    auto isBoxSurface = [&](int s) {
        return s >= 0 && std::size_t(s) < model.surfaces.size()
               && model.surfaces[std::size_t(s)].type == FeatureType::Boundary;
    };
    std::vector<bool> boxLine(model.lines.size(), false);
    vtkNew<vtkCellArray> lines, boxLines;
    for (std::size_t i = 0; i < model.lines.size(); ++i) {
        const Line &line = model.lines[i];
        bool onlyBox = !line.surfaces.empty();
        for (int s : line.surfaces)
            onlyBox = onlyBox && isBoxSurface(s);
        boxLine[i] = onlyBox;
        vtkNew<vtkIdList> ids;
        for (int v : line.vertices)
            if (validVertex(model, v))
                ids->InsertNextId(v);
        if (line.closed && ids->GetNumberOfIds() > 2)
            ids->InsertNextId(ids->GetId(0));
        if (ids->GetNumberOfIds() < 2)
            continue;
        (onlyBox ? boxLines : lines)->InsertNextCell(ids);
        ++m_lineCount;
    }
    vtkNew<vtkCellArray> corners, boxCorners;
    for (const Corner &corner : model.corners) {
        if (!validVertex(model, corner.vertex))
            continue;
        bool onlyBox = !corner.lines.empty();
        for (int l : corner.lines)
            onlyBox =
                onlyBox && l >= 0 && std::size_t(l) < boxLine.size() && boxLine[std::size_t(l)];
        const vtkIdType id = corner.vertex;
        (onlyBox ? boxCorners : corners)->InsertNextCell(1, &id);
        ++m_cornerCount;
    }

    auto points = modelPoints(model);
    auto addLines = [&](vtkCellArray *cells, const QColor &color, double width) {
        auto data = vtkSmartPointer<vtkPolyData>::New();
        data->SetPoints(points);
        data->SetLines(cells);
        auto actor = makeActor(data);
        vtkProperty *p = actor->GetProperty();
        setColor(p, color);
        p->SetLineWidth(float(width));
        p->RenderLinesAsTubesOn();
        p->SetAmbient(0.3);
        m_renderer->AddActor(actor);
        return actor;
    };
    auto addCorners = [&](vtkCellArray *cells, const QColor &color, double size) {
        auto data = vtkSmartPointer<vtkPolyData>::New();
        data->SetPoints(points);
        data->SetVerts(cells);
        auto actor = makeActor(data);
        vtkProperty *p = actor->GetProperty();
        setColor(p, color);
        p->SetPointSize(float(size));
        p->RenderPointsAsSpheresOn();
        p->SetSpecular(0.4);
        p->SetSpecularPower(20.0);
        m_renderer->AddActor(actor);
        return actor;
    };
    m_lines = addLines(lines, contactLineColor(), 3.5);
    m_boxLines = addLines(boxLines, boxLineColor(), 2.0);
    m_corners = addCorners(corners, cornerColor(), 11.0);
    m_boxCorners = addCorners(boxCorners, cornerColor(), 8.0);
}

void ModelScene::buildLegend()
{
    const Model &model = *m_model;
    const FeatureType order[] = {FeatureType::Horizon, FeatureType::Unconformity,
                                 FeatureType::Fault, FeatureType::Unknown, FeatureType::Boundary};
    for (FeatureType type : order) {
        LegendEntry entry;
        entry.type = type;
        entry.color = featureTypeColor(type);
        for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
            const Surface &surface = model.surfaces[i];
            if (surface.type != type)
                continue;
            ++entry.surfaceCount;
            const QString name = QString::fromStdString(surface.featureName);
            if (!entry.featureNames.contains(name)) {
                entry.featureNames.append(name);
                entry.featureColors.push_back(m_surfaceColors[i]);
            }
        }
        entry.featureCount = int(entry.featureNames.size());
        if (entry.surfaceCount > 0)
            m_legend.push_back(entry);
    }
}

void ModelScene::applyVisibility()
{
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i) {
        m_surfaceActors[i]->SetVisibility(m_visible && (!m_isBoxSurface[i] || m_boxVisible)
                                          && m_surfaceShown[i]);
        m_surfaceActors[i]->GetProperty()->SetEdgeVisibility(m_edgesVisible);
    }
    for (auto *actor : {&m_lines, &m_corners})
        if (*actor)
            (*actor)->SetVisibility(m_visible);
    if (m_boxLines)
        m_boxLines->SetVisibility(m_visible && m_boxVisible);
    if (m_boxCorners)
        m_boxCorners->SetVisibility(m_visible && m_boxVisible);
    applyExtrasVisibility();
}

void ModelScene::setVisible(bool visible)
{
    m_visible = visible;
    applyVisibility();
}

void ModelScene::setBoxVisible(bool visible)
{
    m_boxVisible = visible;
    applyVisibility();
}

void ModelScene::setEdgesVisible(bool visible)
{
    m_edgesVisible = visible;
    applyVisibility();
}

double ModelScene::diagonal() const
{
    double b[6];
    return bounds(b) ? std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]) : 1.0;
}

bool ModelScene::bounds(double bounds[6]) const
{
    vtkBoundingBox box;
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i)
        if (vtkPolyData *data = surfaceData(i); data && data->GetNumberOfPoints() > 0)
            box.AddBounds(data->GetBounds());
    if (!box.IsValid())
        return false;
    box.GetBounds(bounds);
    return true;
}

void ModelScene::setSurfaceVisible(int surface, bool visible)
{
    if (surface < 0 || std::size_t(surface) >= m_surfaceShown.size())
        return;
    m_surfaceShown[std::size_t(surface)] = visible;
    applyVisibility();
}

bool ModelScene::surfaceVisible(int surface) const
{
    return surface >= 0 && std::size_t(surface) < m_surfaceShown.size()
           && m_surfaceShown[std::size_t(surface)];
}

vtkActor *ModelScene::surfaceActor(int surface) const
{
    if (surface < 0 || std::size_t(surface) >= m_surfaceActors.size())
        return nullptr;
    return m_surfaceActors[std::size_t(surface)];
}

int ModelScene::surfaceOfActor(const vtkActor *actor) const
{
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i)
        if (m_surfaceActors[i] == actor)
            return int(i);
    return -1;
}

int ModelScene::visibleSurfaceActorCount() const
{
    int n = 0;
    for (const auto &actor : m_surfaceActors)
        n += actor->GetVisibility() ? 1 : 0;
    return n;
}

} // namespace stratamesh
