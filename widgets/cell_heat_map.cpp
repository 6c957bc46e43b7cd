#include "cell_heat_map.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <algorithm>

namespace stratamesh {

CellHeatMap::CellHeatMap(vtkRenderer *renderer)
    : m_renderer(renderer), m_polyData(vtkSmartPointer<vtkPolyData>::New()),
      m_lookupTable(vtkSmartPointer<vtkLookupTable>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()),
      m_scalarBar(vtkSmartPointer<vtkScalarBarActor>::New())
{
    // Blue (few elements) to red (many), as the thesis figure.
    m_lookupTable->SetHueRange(0.667, 0.0);
    m_lookupTable->SetNumberOfTableValues(256);
    m_lookupTable->Build();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(m_polyData);
    mapper->SetLookupTable(m_lookupTable);
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray("count");
    mapper->SetColorModeToMapScalars();
    mapper->ScalarVisibilityOn();
    mapper->UseLookupTableScalarRangeOn();
    // Drawn behind the model's surfaces lying on cell faces.
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(1, 2);
    m_actor->SetMapper(mapper);
    m_actor->GetProperty()->SetEdgeVisibility(true);
    m_actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
    m_actor->GetProperty()->SetLineWidth(0.5);
    m_actor->GetProperty()->SetOpacity(0.55);
    m_actor->PickableOff();
    m_actor->SetVisibility(false);

    m_scalarBar->SetLookupTable(m_lookupTable);
    m_scalarBar->SetNumberOfLabels(5);
    m_scalarBar->SetLabelFormat("%.0f");
    m_scalarBar->SetMaximumWidthInPixels(90);
    m_scalarBar->SetMaximumHeightInPixels(320);
    // Labels on the left of the bar, which sits against the right edge: a narrow view cuts
    // nothing.
    m_scalarBar->SetTextPositionToPrecedeScalarBar();
    m_scalarBar->SetPosition(0.86, 0.08);
    m_scalarBar->SetWidth(0.08);
    m_scalarBar->SetHeight(0.5);
    m_scalarBar->UnconstrainedFontSizeOn();
    m_scalarBar->GetTitleTextProperty()->SetFontSize(14);
    m_scalarBar->GetLabelTextProperty()->SetFontSize(12);
    m_scalarBar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
    m_scalarBar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
    m_scalarBar->GetTitleTextProperty()->ShadowOff();
    m_scalarBar->GetLabelTextProperty()->ShadowOff();
    m_scalarBar->SetVisibility(false);
    m_renderer->AddActor(m_actor);
    m_renderer->AddViewProp(m_scalarBar);
}

CellHeatMap::~CellHeatMap()
{
    m_renderer->RemoveActor(m_actor);
    m_renderer->RemoveViewProp(m_scalarBar);
}

void CellHeatMap::setCells(std::shared_ptr<const std::vector<ConvexPolyhedron>> cells,
                           std::vector<int> counts)
{
    if (cells && cells->size() != counts.size())
        cells = nullptr;
    m_cells = std::move(cells);
    m_counts = m_cells ? std::move(counts) : std::vector<int>{};
    m_maxCount = m_counts.empty() ? 0 : *std::max_element(m_counts.begin(), m_counts.end());
    // The colours do not move with the threshold: a count has one colour. Most cells meet a few
    // elements and a few cells many (thesis Table 3.4): a log scale tells 3 from 6 as well as 20
    // from 40. Counts below 1 take the lowest colour.
    m_lookupTable->SetScaleToLog10();
    m_lookupTable->SetTableRange(1.0, std::max(2, m_maxCount));
    m_lookupTable->Build();
    rebuild();
}

void CellHeatMap::setThreshold(int threshold)
{
    if (threshold == m_threshold)
        return;
    m_threshold = threshold;
    rebuild();
}

void CellHeatMap::setVisible(bool visible)
{
    m_visible = visible;
    m_actor->SetVisibility(m_visible && m_cells && m_shownCells > 0);
    m_scalarBar->SetVisibility(m_visible && m_cells);
}

vtkPolyData *CellHeatMap::polyData() const
{
    return m_polyData;
}

vtkActor *CellHeatMap::actor() const
{
    return m_actor;
}

vtkScalarBarActor *CellHeatMap::scalarBar() const
{
    return m_scalarBar;
}

void CellHeatMap::setTitle(const char *title)
{
    m_scalarBar->SetTitle(title);
}

void CellHeatMap::rebuild()
{
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> polygons;
    vtkNew<vtkIntArray> countArray;
    countArray->SetName("count");
    vtkNew<vtkIntArray> idArray;
    idArray->SetName("CellId");
    m_shownCells = 0;
    if (m_cells) {
        const std::vector<ConvexPolyhedron> &cells = *m_cells;
        const int n = int(cells.size());
        const auto shown = [&](int i) {
            return i >= 0 && i < n && m_counts[i] >= m_threshold && !cells[i].empty();
        };
        for (int i = 0; i < n; ++i) {
            if (!shown(i))
                continue;
            ++m_shownCells;
            const ConvexPolyhedron &cell = cells[i];
            const vtkIdType first = points->GetNumberOfPoints();
            for (const Vec3 &v : cell.vertices())
                points->InsertNextPoint(v.x(), v.y(), v.z());
            for (int f = 0; f < cell.faceCount(); ++f) {
                // A face towards another drawn cell is inside the drawn set (tag = neighbour site).
                if (shown(cell.facePlane(f).tag))
                    continue;
                const int *face = cell.faceBegin(f);
                polygons->InsertNextCell(cell.faceSize(f));
                for (int k = 0; k < cell.faceSize(f); ++k)
                    polygons->InsertCellPoint(first + face[k]);
                countArray->InsertNextValue(m_counts[i]);
                idArray->InsertNextValue(i);
            }
        }
    }
    m_polyData->Initialize();
    m_polyData->SetPoints(points);
    m_polyData->SetPolys(polygons);
    m_polyData->GetCellData()->AddArray(countArray);
    m_polyData->GetCellData()->AddArray(idArray);
    m_polyData->Modified();
    setVisible(m_visible);
}

} // namespace stratamesh
