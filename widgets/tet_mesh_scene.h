// The cells of a volume mesh (TetGen's tets, core/volume, or a hybrid tet/pyramid/prism mesh,
// core/hybrid) drawn in a 3D view, coloured by region, by each cell's minimum dihedral angle
// (thesis §5.2 judges the meshes by it) or by cell type, with a scalar bar as legend. A clip plane
// keeps the whole tets on one side of it, so the inside of the mesh shows cell by cell instead of
// as a cut. This only converts the core's mesh: no geometry here.
#pragma once

#include "mesh/volume_mesh.h"

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <string>

class vtkActor;
class vtkDataSetSurfaceFilter;
class vtkExtractGeometry;
class vtkPlane;
class vtkRenderer;
class vtkScalarBarActor;
class vtkUnstructuredGrid;

namespace stratamesh {

enum class TetColouring { Region, MinDihedral, Type };

class TetMeshScene {
public:
    explicit TetMeshScene(vtkRenderer *renderer);
    ~TetMeshScene();
    TetMeshScene(const TetMeshScene &) = delete;
    TetMeshScene &operator=(const TetMeshScene &) = delete;

    // The cells of the mesh (prisms reordered for VTK_WEDGE); cellQuality, when there is one
    // value per cell, is the min dihedral angle. The scene keeps the mesh alive; nullptr clears.
    void setMesh(std::shared_ptr<const VolumeMesh> mesh);
    const std::shared_ptr<const VolumeMesh> &mesh() const { return m_mesh; }

    void setColouring(TetColouring colouring);
    TetColouring colouring() const { return m_colouring; }
    // Draws only the tets with a node on the side of the plane its normal points away from.
    void setClipPlane(const double origin[3], const double normal[3]);
    void clearClipPlane();
    bool isClipped() const { return m_clipped; }
    void setVisible(bool visible);

    // Titles of the scalar bar (translated by the caller).
    void setTitles(const char *region, const char *minDihedral);
    // Title and names of the cell types' legend, indexed by CellType (translated by the caller).
    void setTypeTitles(const char *title, const std::array<std::string, 3> &names);
    // False without a mesh.
    bool bounds(double bounds[6]) const;
    // Cells of every type (only tets in a TetGen mesh).
    int tetCount() const;
    // Cells drawn after clipping (all of them when not clipped).
    int shownTetCount() const;
    // Range of the min dihedral values drawn; false when there is none.
    bool dihedralRange(double range[2]) const;
    // Number of cells of a type in the drawing.
    int cellCount(CellType type) const;
    vtkActor *actor() const;
    // The cells as handed to VTK (before the clip).
    vtkUnstructuredGrid *grid() const;
    vtkScalarBarActor *scalarBar() const;

    // Minimum dihedral angles are coloured over [0°, kDihedralTop] (70.5° is the regular tet's).
    static constexpr double kDihedralTop = 70.0;

private:
    void applyColouring();
    void applyVisibility();

    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkUnstructuredGrid> m_grid;
    vtkSmartPointer<vtkPlane> m_plane;
    vtkSmartPointer<vtkExtractGeometry> m_extract;
    vtkSmartPointer<vtkDataSetSurfaceFilter> m_surface;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkScalarBarActor> m_scalarBar;
    std::shared_ptr<const VolumeMesh> m_mesh;
    TetColouring m_colouring = TetColouring::Region;
    bool m_clipped = false;
    bool m_visible = true;
    std::string m_regionTitle = "Region";
    std::string m_dihedralTitle = "Min dihedral (°)";
    std::string m_typeTitle = "Cell type";
    std::array<std::string, 3> m_typeNames{"tet", "pyramid", "prism"};
};

} // namespace stratamesh
