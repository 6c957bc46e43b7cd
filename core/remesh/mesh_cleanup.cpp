#include "remesh/mesh_cleanup.h"

#include "common/translate_noop.h"
#include "quality/triangle_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace stratamesh {

std::vector<EntityRef> inputEntitiesOf(const EditableSoup &soup, const Model &input,
                                       const std::vector<int> &points)
{
    std::vector<EntityRef> refs;
    for (int p : points) {
        const OutputPoint &op = soup.point(p);
        for (int s : op.surfaces)
            addUnique(refs, surfaceRef(input, s));
        for (int l : op.lines)
            addUnique(refs, lineRef(input, l));
        for (int c : op.corners)
            addUnique(refs, cornerRef(input, c));
    }
    return refs;
}

namespace {

LedgerRecord makeRecord(LedgerKind kind, const EditableSoup &soup, const Model &input,
                        const std::vector<int> &points, const Vec3 &position, double size,
                        const char *note)
{
    LedgerRecord r;
    r.kind = kind;
    r.inputs = inputEntitiesOf(soup, input, points);
    for (int p : points)
        r.outputs.push_back(vertexRef(p));
    r.position = position;
    r.size = size;
    r.sizeMeaning = "distance";
    setNote(r, {note, {}});
    return r;
}

double pointPlaneDistance(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    return len > 0.0 ? std::abs((p - a).dot(n)) / len : (p - a).norm();
}

Vec3 projectOnSegment(const Vec3 &x, const Vec3 &a, const Vec3 &b)
{
    const Vec3 d = b - a;
    const double l2 = d.squaredNorm();
    const double t = l2 > 0.0 ? std::clamp((x - a).dot(d) / l2, 0.0, 1.0) : 0.0;
    return a + t * d;
}

bool touchesFreeBorder(const EditableSoup &soup, const OutputTriangle &t)
{
    for (int k = 0; k < 3; ++k)
        if (soup.edgeTriangles(t.v[k], t.v[(k + 1) % 3]).size() == 1)
            return true;
    return false;
}

} // namespace

CleanupCounts removeValence3Vertices(EditableSoup &soup, const Model &input,
                                     SimplificationLedger &ledger)
{
    CleanupCounts counts;
    for (bool changed = true; changed;) {
        changed = false;
        for (int v = 0; v < soup.pointCount(); ++v) {
            const std::vector<int> tris = soup.vertexTriangles(v);
            if (tris.size() != 3 || soup.vertexClass(v) != VertexClass::Interior)
                continue;
            // The fan's outer edges, each oriented as in its triangle, chain into the new triangle.
            std::array<std::pair<int, int>, 3> outer;
            Vec3 normalSum = Vec3::Zero();
            for (int i = 0; i < 3; ++i) {
                const OutputTriangle &t = soup.triangle(tris[i]);
                const int k = cornerIndex(t, v);
                outer[i] = {t.v[(k + 1) % 3], t.v[(k + 2) % 3]};
                normalSum += soup.normal(tris[i]);
            }
            const int a = outer[0].first, b = outer[0].second;
            int c = -1;
            for (int i = 1; i < 3; ++i)
                if (outer[i].first == b)
                    c = outer[i].second;
            if (c < 0 || c == a)
                continue;
            const Vec3 &pa = soup.position(a), &pb = soup.position(b), &pc = soup.position(c);
            if ((pb - pa).cross(pc - pa).dot(normalSum) <= 0.0
                || triangleQuality(pa, pb, pc) <= 0.0)
                continue;
            bool exists = false;
            for (int t : soup.vertexTriangles(a))
                exists = exists
                         || (cornerIndex(soup.triangle(t), b) >= 0
                             && cornerIndex(soup.triangle(t), c) >= 0);
            if (exists)
                continue;
            const int surface = soup.triangle(tris[0]).surface;
            ledger.push_back(makeRecord(
                LedgerKind::Valence3Removed, soup, input, {v}, soup.position(v),
                pointPlaneDistance(soup.position(v), pa, pb, pc),
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "valence-3 vertex of a tiny cell removed (Fig 4.8a)")));
            for (int t : tris)
                soup.removeTriangle(t);
            soup.addTriangle({a, b, c}, surface);
            ++counts.valence3;
            changed = true;
        }
    }
    return counts;
}

namespace {

// One attempt on one degenerate triangle; returns true when the mesh changed.
bool fixDegenerate(EditableSoup &soup, int t, const Model &input, const CleanupParams &params,
                   SimplificationLedger &ledger, CleanupCounts &counts)
{
    const OutputTriangle tri = soup.triangle(t);
    const std::array<Vec3, 3> p{soup.position(tri.v[0]), soup.position(tri.v[1]),
                                soup.position(tri.v[2])};
    const TriangleShape shape = triangleShape(p[0], p[1], p[2]);
    const double minQ = 0.5 * params.degenerateQuality;
    const Vec3 centre = (p[0] + p[1] + p[2]) / 3.0;
    const bool onBorder = touchesFreeBorder(soup, tri);
    int apex = 0;
    for (int k = 1; k < 3; ++k)
        if (shape.anglesDeg[k] > shape.anglesDeg[apex])
            apex = k;

    if (shape.anglesDeg[apex] > params.capAngleDeg) {
        const int r = tri.v[apex], a = tri.v[(apex + 1) % 3], b = tri.v[(apex + 2) % 3];
        const std::size_t along = soup.edgeTriangles(a, b).size();
        if (!soup.isFeatureEdge(a, b)) {
            if (soup.flip(a, b)) {
                ++counts.flips;
                return true;
            }
        } else if (along == 1) {
            // Fig 4.8b: the apex joins the free border, or leaves it when it only had this
            // triangle.
            const VertexClass rc = soup.vertexClass(r);
            if (rc == VertexClass::Interior || soup.vertexTriangles(r).size() == 1) {
                const double size =
                    (soup.position(r)
                     - projectOnSegment(soup.position(r), soup.position(a), soup.position(b)))
                        .norm();
                ledger.push_back(makeRecord(
                    LedgerKind::DegenerateBorderTriangle, soup, input, {r, a, b}, centre, size,
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "degenerate triangle on a free border removed (Fig 4.8b)")));
                soup.removeTriangle(t);
                ++counts.borderTriangles;
                return true;
            }
        } else if (soup.vertexClass(r) == VertexClass::Interior) {
            // Algorithm 4.4, configuration 6: the apex is inserted into the contact edge.
            const Vec3 target =
                projectOnSegment(soup.position(r), soup.position(a), soup.position(b));
            const double moved = (target - soup.position(r)).norm();
            soup.removeTriangle(t);
            if (!soup.tryMove(r, target, minQ)) {
                soup.addTriangle(tri.v, tri.surface);
                return false;
            }
            soup.splitEdge(a, b, r);
            ledger.push_back(makeRecord(
                LedgerKind::DegenerateContactTriangle, soup, input, {r, a, b}, centre, moved,
                QT_TRANSLATE_NOOP("stratamesh::Core", "cap along a contact: vertex inserted into "
                                                      "the contact (Alg 4.4, configuration 6)")));
            ++counts.contactTriangles;
            return true;
        }
    }

    // Needle: collapse its shortest edge (Algorithm 4.4, configuration 9, when off the contact).
    int e = 0;
    double shortest = (p[1] - p[0]).norm();
    for (int k = 1; k < 3; ++k) {
        const double l = (p[(k + 1) % 3] - p[k]).norm();
        if (l < shortest) {
            shortest = l;
            e = k;
        }
    }
    int x = tri.v[e], y = tri.v[(e + 1) % 3];
    VertexClass cx = soup.vertexClass(x), cy = soup.vertexClass(y);
    if (cx != VertexClass::Interior && cy == VertexClass::Interior) {
        std::swap(x, y);
        std::swap(cx, cy);
    }
    Vec3 target;
    if (cx == VertexClass::Interior && cy == VertexClass::Interior)
        target = 0.5 * (soup.position(x) + soup.position(y));
    else if (cx == VertexClass::Interior)
        target = soup.position(y);
    else if (soup.isFeatureEdge(x, y) && cx == VertexClass::Line && cy == VertexClass::Line)
        target = 0.5 * (soup.position(x) + soup.position(y));
    else if (soup.isFeatureEdge(x, y) && cx == VertexClass::Line && cy == VertexClass::Fixed)
        target = soup.position(y);
    else if (soup.isFeatureEdge(x, y) && cx == VertexClass::Fixed && cy == VertexClass::Line) {
        std::swap(x, y);
        target = soup.position(y);
    } else
        return false;
    const bool interiorOnly = cx == VertexClass::Interior && cy == VertexClass::Interior
                              && soup.vertexClass(tri.v[(e + 2) % 3]) == VertexClass::Interior;
    const double moved =
        std::max((target - soup.position(x)).norm(), (target - soup.position(y)).norm());
    const std::vector<int> involved{x, y};
    const LedgerRecord record = makeRecord(
        onBorder ? LedgerKind::DegenerateBorderTriangle : LedgerKind::DegenerateContactTriangle,
        soup, input, involved, centre, moved,
        "needle: its short edge collapsed (Alg 4.4, configuration 9)");
    if (!soup.collapse(x, y, target, minQ))
        return false;
    if (interiorOnly) {
        ++counts.interiorCollapses;
    } else {
        ledger.push_back(record);
        ++(onBorder ? counts.borderTriangles : counts.contactTriangles);
    }
    return true;
}

} // namespace

CleanupCounts removeDegenerateTriangles(EditableSoup &soup, const Model &input,
                                        const CleanupParams &params, SimplificationLedger &ledger)
{
    CleanupCounts counts;
    for (int pass = 0; pass < params.maxPasses; ++pass) {
        bool changed = false;
        // Triangles made during the pass wait for the next one: a cap whose apex cannot move onto
        // its contact is put back as a new triangle, and meeting it again in the same pass made
        // the pass endless (nested spheres from box sites, a non-manifold edge of 4 triangles).
        const int end = soup.triangleCapacity();
        for (int t = 0; t < end; ++t) {
            if (!soup.alive(t) || soup.quality(t) >= params.degenerateQuality)
                continue;
            changed = fixDegenerate(soup, t, input, params, ledger, counts) || changed;
        }
        if (!changed)
            break;
    }
    return counts;
}

int improveByFlips(EditableSoup &soup, int maxPasses)
{
    int flips = 0;
    for (int pass = 0; pass < maxPasses; ++pass) {
        int passFlips = 0;
        for (int t = 0; t < soup.triangleCapacity(); ++t) {
            if (!soup.alive(t))
                continue;
            const OutputTriangle tri = soup.triangle(t);
            for (int k = 0; k < 3 && soup.alive(t); ++k)
                if (soup.flip(tri.v[k], tri.v[(k + 1) % 3]))
                    ++passFlips;
        }
        flips += passFlips;
        if (passFlips == 0)
            break;
    }
    return flips;
}

} // namespace stratamesh
