// A triangle soup with shared vertex ids and per-triangle surface tags, editable in place by the
// post-processing of thesis §4.4.5 (valence-3 removal, degenerate triangles on borders and along
// contacts with Algorithm 4.4, intersection repair). Vertex classes come from the mesh itself:
// an edge is a feature edge when it is not shared by exactly two consistently oriented triangles
// of one surface (free border, contact, non-manifold); the operations never change which edges
// are feature edges except where a ledger record says so, which keeps contacts sealed.
#pragma once

#include "remesh/output_mesh.h"

#include <array>
#include <vector>

namespace stratamesh {

enum class VertexClass {
    Interior, // inside one surface, a single closed fan
    Line,     // on exactly two feature edges of the same kind (a contact or border polyline)
    Fixed,    // corners, line ends, non-manifold points: never moved nor removed
};

class EditableSoup {
public:
    explicit EditableSoup(OutputMesh mesh);

    // Alive triangles only, unreferenced points dropped.
    OutputMesh result() const;

    int pointCount() const { return static_cast<int>(m_mesh.points.size()); }
    int triangleCapacity() const { return static_cast<int>(m_mesh.triangles.size()); }
    bool alive(int t) const { return m_alive[t]; }
    const OutputTriangle &triangle(int t) const { return m_mesh.triangles[t]; }
    const OutputPoint &point(int v) const { return m_mesh.points[v]; }
    OutputPoint &point(int v) { return m_mesh.points[v]; }
    const Vec3 &position(int v) const { return m_mesh.points[v].position; }

    // Alive triangles around a vertex / along an edge.
    const std::vector<int> &vertexTriangles(int v) const { return m_vertexTriangles[v]; }
    std::vector<int> edgeTriangles(int a, int b) const;
    std::vector<int> neighbours(int v) const;

    bool isFeatureEdge(int a, int b) const;
    VertexClass vertexClass(int v) const;
    int featureEdgeCount(int v) const;

    int addTriangle(const std::array<int, 3> &v, int surface);
    int addPoint(const OutputPoint &p);
    void removeTriangle(int t);

    // Moves u onto w (w at `target`): triangles with both die, the others now use w. Checks the
    // link condition, that no remaining triangle flips or becomes a needle worse than minQuality,
    // and that no duplicate triangle appears. Returns false (and changes nothing) when refused.
    // checkShape = false skips the flip and quality checks (the caller judges the result).
    bool collapse(int u, int w, const Vec3 &target, double minQuality, bool checkShape = true);
    // Flips the interior edge (a, b) of one surface. Refused when (c, d) is already an edge, when
    // a triangle would flip, or when the smaller quality does not improve.
    bool flip(int a, int b, bool requireImprovement = true);
    // Inserts vertex x into edge (a, b) of every triangle holding that edge but not x.
    void splitEdge(int a, int b, int x);
    // Moves a vertex when no incident triangle flips nor drops below minQuality.
    bool tryMove(int v, const Vec3 &target, double minQuality);

    // Normal (not unit) of a triangle, and its quality.
    Vec3 normal(int t) const;
    double quality(int t) const;

private:
    // Up to three alive triangles along an edge, without allocating (the flips and feature tests
    // run over every edge several times); returns how many there are, capped at three.
    int edgeTrianglesUpTo3(int a, int b, std::array<int, 3> &out) const;
    bool wouldFlip(int v, const Vec3 &target, const std::vector<int> &skip, int replaceBy,
                   double minQuality) const;
    bool triangleExists(const std::array<int, 3> &v, int ignore1, int ignore2) const;

    OutputMesh m_mesh;
    std::vector<bool> m_alive;
    std::vector<std::vector<int>> m_vertexTriangles;
};

// Index of vertex v in triangle t (-1 when absent).
int cornerIndex(const OutputTriangle &t, int v);
// True when t goes a → b (rather than b → a).
bool hasDirectedEdge(const OutputTriangle &t, int a, int b);

} // namespace stratamesh
