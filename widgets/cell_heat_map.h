// The Voronoi cells of a local complexity run drawn as a heat map in a 3D view (thesis Fig 3.7):
// each cell coloured by the number of model elements it meets, with a scalar bar. Only cells
// whose count reaches a threshold are drawn, so the many low-count cells do not hide the model;
// faces shared by two drawn cells are left out, as they cannot be seen. This only converts the
// core's polyhedra (vertices and faces) into VTK polygons: no geometry is computed here.
#pragma once

#include "complexity/convex_polyhedron.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

class vtkActor;
class vtkLookupTable;
class vtkPolyData;
class vtkRenderer;
class vtkScalarBarActor;

namespace stratamesh {

class CellHeatMap {
public:
    explicit CellHeatMap(vtkRenderer *renderer);
    ~CellHeatMap();
    CellHeatMap(const CellHeatMap &) = delete;
    CellHeatMap &operator=(const CellHeatMap &) = delete;

    // counts[i] belongs to cells[i]; the cells are kept alive. nullptr clears.
    void setCells(std::shared_ptr<const std::vector<ConvexPolyhedron>> cells,
                  std::vector<int> counts);
    void clear() { setCells(nullptr, {}); }
    bool hasCells() const { return m_cells != nullptr; }

    // Cells with a count >= threshold are drawn.
    void setThreshold(int threshold);
    int threshold() const { return m_threshold; }
    void setVisible(bool visible);
    bool isVisible() const { return m_visible; }

    // Number of cells passing the threshold (drawn unless hidden).
    int shownCellCount() const { return m_shownCells; }
    int maxCount() const { return m_maxCount; }
    // The drawn polygons, with cell arrays "count" and "CellId" (index of the core's cell).
    vtkPolyData *polyData() const;
    vtkActor *actor() const;
    vtkScalarBarActor *scalarBar() const;
    // Title of the scalar bar (translated by the caller).
    void setTitle(const char *title);

private:
    void rebuild();

    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkPolyData> m_polyData;
    vtkSmartPointer<vtkLookupTable> m_lookupTable;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkScalarBarActor> m_scalarBar;
    std::shared_ptr<const std::vector<ConvexPolyhedron>> m_cells;
    std::vector<int> m_counts;
    int m_threshold = 3;
    int m_shownCells = 0;
    int m_maxCount = 0;
    bool m_visible = true;
};

} // namespace stratamesh
