// A convex polyhedron cut by half-spaces: the clipped Voronoi cells of the volumetric CVT used for
// the local complexity measures (thesis §3.3.2, §3.5.2; Voronoi cells §1.1.1).
//
// Each face remembers the plane that made it (a tag: the neighbour site, or a box side), so a cell
// is both a vertex/face mesh (for export and heat maps) and a list of half-spaces (for clipping
// triangles and segments against it). Vertices on a cutting plane within a tolerance are kept as
// they are and not split, which keeps faces shared between clips consistent without exact numbers.
#pragma once

#include "model/model.h"

#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace stratamesh {

using Box3 = Eigen::AlignedBox3d;

// The closed half-space normal·x <= offset; the face it makes carries tag.
struct HalfSpace {
    Vec3 normal = Vec3::Zero();
    double offset = 0.0;
    int tag = -1;
};

// Tags of the six faces of a box cell: -1 xmin, -2 xmax, -3 ymin, -4 ymax, -5 zmin, -6 zmax.
inline int boxSideTag(int axis, bool upper)
{
    return -1 - (2 * axis + (upper ? 1 : 0));
}

// Scratch buffers of ConvexPolyhedron::clip(); reusing one per thread avoids allocations.
struct ClipWorkspace {
    std::vector<signed char> side;
    std::vector<double> dist;
    std::vector<int> out;
    std::vector<int> capNext;
    std::vector<int> capVertices;
    std::vector<std::array<int, 3>> edgeVertex; // (a, b, new vertex), a < b
    std::vector<int> faceStart;
    std::vector<int> faceVertices;
    std::vector<HalfSpace> planes;
    std::vector<int> remap;
};

class ConvexPolyhedron {
public:
    ConvexPolyhedron() = default;
    // The box as a polyhedron; eps (distance below which a vertex is on a plane) scales with it.
    static ConvexPolyhedron box(const Box3 &box);

    // Keeps the part where normal·x <= offset (normal need not be unit). Returns true when the
    // polyhedron changed (possibly to empty).
    bool clip(const HalfSpace &halfSpace);
    bool clip(const HalfSpace &halfSpace, ClipWorkspace &workspace);

    bool empty() const { return m_planes.empty(); }
    const std::vector<Vec3> &vertices() const { return m_vertices; }
    int faceCount() const { return static_cast<int>(m_planes.size()); }
    // Vertex ids of face f, counter-clockwise seen from outside.
    const int *faceBegin(int f) const { return m_faceVertices.data() + m_faceStart[f]; }
    int faceSize(int f) const { return m_faceStart[f + 1] - m_faceStart[f]; }
    const HalfSpace &facePlane(int f) const { return m_planes[f]; }
    const std::vector<HalfSpace> &planes() const { return m_planes; }
    double tolerance() const { return m_eps; }

    double volume() const;
    Vec3 centroid() const;
    // ∫ |x - point|² over the polyhedron: the CVT energy of a cell about its site.
    double secondMoment(const Vec3 &point) const;
    Box3 bounds() const;
    double maxSquaredDistance(const Vec3 &point) const;
    // Inside or on the boundary within tolerance().
    bool contains(const Vec3 &point) const;

private:
    void compact(std::vector<int> &remap);
    void addCapFace(const HalfSpace &plane, const std::vector<int> &capNext,
                    const std::vector<int> &capVertices);

    std::vector<Vec3> m_vertices;
    std::vector<int> m_faceStart{0}; // faceCount() + 1 entries into m_faceVertices
    std::vector<int> m_faceVertices;
    std::vector<HalfSpace> m_planes; // one per face
    double m_eps = 0.0;
};

} // namespace stratamesh
