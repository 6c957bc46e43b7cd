// Names shared by the VTK writer and reader, and capture of VTK's error messages.
#pragma once

#include "common/message_text.h"

#include <array>
#include <string>

class vtkObject;

namespace stratamesh {

namespace vtkarrays {
constexpr const char *regionId = "RegionId";
constexpr const char *surfaceId = "SurfaceId";
constexpr const char *lineId = "LineId";
constexpr const char *cellType = "CellType";
constexpr const char *meshName = "MeshName";
constexpr const char *zPositiveDepth = "ZPositiveDepth";
constexpr const char *regionNames = "RegionNames";
constexpr const char *surfaceNames = "SurfaceNames";
constexpr const char *surfaceFeatures = "SurfaceFeatures";
constexpr const char *surfaceTypes = "SurfaceTypes";
constexpr const char *lineNames = "LineNames";
constexpr const char *qualityName = "QualityName";
constexpr const char *regionSides = "RegionSides";
} // namespace vtkarrays

// VTK_WEDGE node i is our prism node wedgeMap[i] (and the reverse: the map is its own inverse).
constexpr std::array<int, 6> vtkWedgeMap{0, 2, 1, 3, 5, 4};

// Why cell `cell` (numbered from 0) of VTK type `type` with these `count` point ids cannot be
// read, checked in this order: a point-id count its type does not have, a type StrataMesh does
// not exchange (tets, pyramids, wedges, triangles, lines, vertices), a point id outside
// 0..points-1. An empty pattern when it can be read. Shared by the XML path and the legacy parser,
// so that both refuse the same cells in the same words.
MessageText vtkCellProblem(long long cell, int type, const long long *ids, long long count,
                           long long points);

// Collects the ErrorEvent messages of a VTK object instead of printing them.
class VtkErrorCapture {
public:
    explicit VtkErrorCapture(vtkObject *object);
    ~VtkErrorCapture();
    VtkErrorCapture(const VtkErrorCapture &) = delete;
    VtkErrorCapture &operator=(const VtkErrorCapture &) = delete;
    const std::string &message() const { return m_message; }
    bool failed() const { return !m_message.empty(); }
    // Warnings, kept apart: a writer may go on, a reader may not.
    const std::string &warnings() const { return m_warnings; }

private:
    vtkObject *m_object;
    unsigned long m_errorTag = 0;
    unsigned long m_warningTag = 0;
    std::string m_message;
    std::string m_warnings;
};

} // namespace stratamesh
