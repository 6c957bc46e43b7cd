// Turns a Model into VTK actors: surfaces coloured by feature type, contact lines, corners.
// It only converts what the core computed (vertices, triangles, lines, corners): no geometry here.
#pragma once

#include "model/model.h"

#include <QColor>
#include <QString>

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkActor;
class vtkClipPolyData;
class vtkDataArray;
class vtkLookupTable;
class vtkPlane;
class vtkPolyData;
class vtkRenderer;
class vtkScalarBarActor;

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

    // --- Colouring by a measure, clip plane and highlighted triangles (View menu) ---
    // `values`: per surface (indexed like Model::surfaces), one per triangle, or per vertex when
    // `perVertex`, all computed by the core. A surface whose count differs from what is drawn
    // keeps its entity colour. The table and its range are the caller's, so that two scenes
    // compare; the scalar bar shows `title`.
    void setScalarColouring(const std::vector<std::vector<double>> &values, bool perVertex,
                            vtkLookupTable *table, const std::string &title);
    // Back to the entity colours.
    void clearScalarColouring();
    bool hasScalarColouring() const;
    vtkScalarBarActor *scalarBar() const;
    vtkLookupTable *lookupTable() const;
    // The scalars handed to a surface's mapper; nullptr when it is not coloured by a measure.
    vtkDataArray *surfaceScalars(int surface) const;
    // Keeps what lies on the side of the plane its normal points away from (as TetMeshScene), in
    // surfaces, lines, corners and highlight; kept across setModel().
    void setClipPlane(const double origin[3], const double normal[3]);
    void clearClipPlane();
    bool isClipped() const { return m_clipped; }
    // Triangles drawn in the visible surfaces once clipped (cut triangles count as pieces).
    int shownTriangleCount() const;
    // Draws these triangles (surface, triangle) over the surfaces in a highlight colour; those of
    // the box only while the box is shown.
    void setHighlight(const std::vector<std::pair<int, int>> &triangles);
    void clearHighlight() { setHighlight({}); }
    int highlightCount() const { return m_highlightCount; }

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

    // Colouring by a measure, clip plane and highlight (model_scene_extras.cpp).
    vtkPolyData *surfaceData(std::size_t surface) const;
    void clearExtras();
    void applyClip();
    void applyExtrasVisibility();
    vtkSmartPointer<vtkLookupTable> m_scalarTable;
    vtkSmartPointer<vtkScalarBarActor> m_scalarBar;
    std::vector<vtkSmartPointer<vtkClipPolyData>> m_clips; // one per surface while clipped
    // Lines, box lines, corners, box corners, highlight, box highlight while clipped.
    std::array<vtkSmartPointer<vtkClipPolyData>, 6> m_otherClips;
    vtkSmartPointer<vtkPlane> m_plane;
    vtkSmartPointer<vtkActor> m_highlight;
    vtkSmartPointer<vtkActor> m_boxHighlight; // shown with the box only
    int m_highlightCount = 0;
    bool m_clipped = false;
};

} // namespace stratamesh
