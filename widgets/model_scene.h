// Turns a Model into VTK actors: surfaces coloured by feature type, contact lines, corners.
// It only converts what the core computed (vertices, triangles, lines, corners): no geometry here.
#pragma once

#include "model/model.h"

#include <QColor>
#include <QString>

#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace stratamesh {

struct LegendEntry {
    FeatureType type = FeatureType::Unknown;
    QColor color;
    int featureCount = 0;
    int surfaceCount = 0;
    QStringList featureNames;          // in model order
    std::vector<QColor> featureColors; // colour of each feature's first surface
};

class ModelScene {
public:
    explicit ModelScene(vtkRenderer *renderer);
    ~ModelScene();
    ModelScene(const ModelScene &) = delete;
    ModelScene &operator=(const ModelScene &) = delete;

    // Replaces the displayed model (nullptr clears). The scene keeps the model alive.
    void setModel(std::shared_ptr<const Model> model);
    const std::shared_ptr<const Model> &model() const { return m_model; }

    // Box surfaces (Boundary type) and the lines and corners lying only on them.
    void setBoxVisible(bool visible);
    bool boxVisible() const { return m_boxVisible; }
    void setEdgesVisible(bool visible);
    bool edgesVisible() const { return m_edgesVisible; }
    // The whole model, e.g. while its tetrahedra are drawn in its place.
    void setVisible(bool visible);
    bool isVisible() const { return m_visible; }

    // One entry per feature type present, box last, in a stable order.
    const std::vector<LegendEntry> &legend() const { return m_legend; }
    // Colour given to each surface, indexed like Model::surfaces.
    const std::vector<QColor> &surfaceColors() const { return m_surfaceColors; }

    // Bounds of the whole model, hidden box included, so that showing the box never needs a
    // new camera. False when there is nothing to show.
    bool bounds(double bounds[6]) const;
    // Diagonal of those bounds; 1 when there is nothing to show (a scale for markers, spin boxes).
    double diagonal() const;

    // One surface shown or hidden by the user (the model tree); the box toggle and setVisible
    // still apply on top. Indexed like Model::surfaces; out of range is ignored.
    void setSurfaceVisible(int surface, bool visible);
    bool surfaceVisible(int surface) const;
    // The actor drawing one surface (nullptr out of range): overlays and pickers use it.
    vtkActor *surfaceActor(int surface) const;
    // The surface drawn by `actor`, or -1.
    int surfaceOfActor(const vtkActor *actor) const;

    int surfaceActorCount() const { return int(m_surfaceActors.size()); }
    int visibleSurfaceActorCount() const;
    int lineCount() const { return m_lineCount; }
    int cornerCount() const { return m_cornerCount; }

private:
    void clear();
    void buildSurfaces();
    void buildLinesAndCorners();
    void buildLegend();
    void applyVisibility();

    vtkSmartPointer<vtkRenderer> m_renderer; // kept alive until our actors are removed
    std::shared_ptr<const Model> m_model;
    bool m_boxVisible = false;
    bool m_edgesVisible = false;
    bool m_visible = true;

    std::vector<vtkSmartPointer<vtkActor>> m_surfaceActors; // one per surface
    std::vector<bool> m_isBoxSurface;
    std::vector<bool> m_surfaceShown; // the user's per-surface choice
    vtkSmartPointer<vtkActor> m_lines;
    vtkSmartPointer<vtkActor> m_boxLines;
    vtkSmartPointer<vtkActor> m_corners;
    vtkSmartPointer<vtkActor> m_boxCorners;
    std::vector<QColor> m_surfaceColors;
    std::vector<LegendEntry> m_legend;
    int m_lineCount = 0;
    int m_cornerCount = 0;
};

} // namespace stratamesh
