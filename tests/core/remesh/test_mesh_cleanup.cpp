// Post-processing of thesis §4.4.5 on small meshes built in code.
#include "remesh/editable_soup.h"
#include "remesh/mesh_cleanup.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <map>
#include <set>

using namespace stratamesh;

namespace {

// n × n grid of squares on plane z = 0 (x, y in [0, n]), surface tag 0, each square split in two.
OutputMesh grid(int n, int surface = 0)
{
    OutputMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            OutputPoint p;
            p.position = Vec3(i, j, 0);
            p.surfaces.assign(1, surface);
            m.points.push_back(p);
        }
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, surface});
            m.triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}, surface});
        }
    return m;
}

int addPoint(OutputMesh &m, const Vec3 &p, int surface)
{
    OutputPoint op;
    op.position = p;
    op.surfaces.assign(1, surface);
    m.points.push_back(op);
    return static_cast<int>(m.points.size()) - 1;
}

// Edge → number of triangles per surface, to check borders and contacts.
std::map<std::pair<int, int>, std::map<int, int>> edgeUse(const OutputMesh &m)
{
    std::map<std::pair<int, int>, std::map<int, int>> use;
    for (const OutputTriangle &t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = t.v[k], b = t.v[(k + 1) % 3];
            ++use[{std::min(a, b), std::max(a, b)}][t.surface];
        }
    return use;
}

double totalArea(const OutputMesh &m, int surface)
{
    double a = 0;
    for (const OutputTriangle &t : m.triangles)
        if (t.surface == surface)
            a += 0.5
                 * (m.points[t.v[1]].position - m.points[t.v[0]].position)
                       .cross(m.points[t.v[2]].position - m.points[t.v[0]].position)
                       .norm();
    return a;
}

// Every edge used by surface 0 on y = 0 is also used by surface 1: the contact stays sealed.
bool contactSealed(const OutputMesh &m)
{
    for (const auto &[edge, bySurface] : edgeUse(m)) {
        const Vec3 &a = m.points[edge.first].position, &b = m.points[edge.second].position;
        const bool onContact = std::abs(a.y()) < 1e-12 && std::abs(b.y()) < 1e-12
                               && std::abs(a.z()) < 1e-12 && std::abs(b.z()) < 1e-12;
        if (onContact && bySurface.size() != 2)
            return false;
        if (!onContact && bySurface.size() != 1)
            return false;
    }
    return true;
}

// Surface 0: grid on z = 0 for y in [0, n]; surface 1: grid on y = 0 for z in [-n, 0] sharing the
// points of the line y = z = 0 (a contact).
OutputMesh contactPair(int n)
{
    OutputMesh m = grid(n, 0);
    std::vector<int> line(n + 1);
    for (int i = 0; i <= n; ++i)
        line[i] = i;
    std::vector<std::vector<int>> ids(n + 1, std::vector<int>(n + 1));
    for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= n; ++i)
            ids[k][i] = k == 0 ? line[i] : addPoint(m, Vec3(i, 0, -k), 1);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({{ids[k][i], ids[k + 1][i + 1], ids[k][i + 1]}, 1});
            m.triangles.push_back({{ids[k][i], ids[k + 1][i], ids[k + 1][i + 1]}, 1});
        }
    return m;
}

} // namespace

class TestMeshCleanup : public QObject {
    Q_OBJECT
private slots:
    void vertexClasses()
    {
        const EditableSoup soup(contactPair(3));
        QCOMPARE(soup.vertexClass(5), VertexClass::Interior); // (1,1,0)
        QCOMPARE(soup.vertexClass(1), VertexClass::Line);     // (1,0,0): on the contact
        QCOMPARE(soup.vertexClass(0), VertexClass::Fixed);    // contact end meets two borders
        QCOMPARE(soup.vertexClass(4), VertexClass::Line);     // (0,1,0): free border
    }

    void valence3VertexRemoved()
    {
        OutputMesh m = grid(3);
        // Split triangle (5, 6, 10) — points (1,1), (2,1), (2,2) — by a vertex inside it.
        const int inside = addPoint(m, Vec3(1.7, 1.3, 0.05), 0);
        int split = -1;
        for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
            if (m.triangles[t].v == std::array<int, 3>{5, 6, 10})
                split = t;
        QVERIFY(split >= 0);
        m.triangles.erase(m.triangles.begin() + split);
        m.triangles.push_back({{5, 6, inside}, 0});
        m.triangles.push_back({{6, 10, inside}, 0});
        m.triangles.push_back({{10, 5, inside}, 0});
        const std::size_t before = m.triangles.size();
        EditableSoup soup(m);
        SimplificationLedger ledger;
        Model input;
        const CleanupCounts c = removeValence3Vertices(soup, input, ledger);
        QCOMPARE(c.valence3, 1);
        const OutputMesh out = soup.result();
        QCOMPARE(out.triangles.size(), before - 2);
        QCOMPARE(out.points.size(), std::size_t(16));
        QCOMPARE(countKind(ledger, LedgerKind::Valence3Removed), 1);
        QVERIFY(std::abs(ledger[0].size - 0.05) < 1e-12);
        QVERIFY(std::abs(totalArea(out, 0) - 9.0) < 1e-12);
        for (const auto &[edge, use] : edgeUse(out)) // still a manifold disc
            QVERIFY(use.at(0) <= 2);
    }

    void capOnFreeBorderRemoved()
    {
        OutputMesh m = grid(2);
        // A vertex just inside the bottom border between (0,0) and (1,0) makes the cap (0, 1, r).
        const int r = addPoint(m, Vec3(0.5, 0.01, 0), 0);
        // Replace triangle (0, 1, 4) by (0, 1, r), (0, r, 4), (r, 1, 4).
        for (auto it = m.triangles.begin(); it != m.triangles.end(); ++it)
            if (it->v == std::array<int, 3>{0, 1, 4}) {
                m.triangles.erase(it);
                break;
            }
        m.triangles.push_back({{0, 1, r}, 0});
        m.triangles.push_back({{0, r, 4}, 0});
        m.triangles.push_back({{r, 1, 4}, 0});
        EditableSoup soup(m);
        SimplificationLedger ledger;
        const CleanupCounts c = removeDegenerateTriangles(soup, Model{}, CleanupParams{}, ledger);
        QCOMPARE(c.borderTriangles, 1);
        QCOMPARE(countKind(ledger, LedgerKind::DegenerateBorderTriangle), 1);
        const OutputMesh out = soup.result();
        QCOMPARE(out.triangles.size(), std::size_t(9));
        // r is now on the border: edges (0, r) and (r, 1) have one triangle each.
        int borderEdges = 0;
        for (const auto &[edge, use] : edgeUse(out))
            borderEdges += use.at(0) == 1 ? 1 : 0;
        QCOMPARE(borderEdges, 9);
    }

    void capAlongContactInsertedIntoIt()
    {
        OutputMesh m = contactPair(2);
        // In surface 0, a vertex r very close to the contact edge (0, 1): cap (0, 1, r).
        const int r = addPoint(m, Vec3(0.5, 0.01, 0), 0);
        for (auto it = m.triangles.begin(); it != m.triangles.end(); ++it)
            if (it->v == std::array<int, 3>{0, 1, 4}) {
                m.triangles.erase(it);
                break;
            }
        m.triangles.push_back({{0, 1, r}, 0});
        m.triangles.push_back({{0, r, 4}, 0});
        m.triangles.push_back({{r, 1, 4}, 0});
        EditableSoup soup(m);
        SimplificationLedger ledger;
        const CleanupCounts c = removeDegenerateTriangles(soup, Model{}, CleanupParams{}, ledger);
        QCOMPARE(c.contactTriangles, 1);
        QCOMPARE(countKind(ledger, LedgerKind::DegenerateContactTriangle), 1);
        const OutputMesh out = soup.result();
        QVERIFY(contactSealed(out)); // r moved onto the contact and is used by both surfaces
        QVERIFY(std::abs(totalArea(out, 0) - 4.0) < 1e-12);
        QVERIFY(std::abs(totalArea(out, 1) - 4.0) < 1e-12);
        QVERIFY(std::abs(ledger[0].size - 0.01) < 1e-12);
    }

    void interiorNeedleCollapsed()
    {
        OutputMesh m = contactPair(2);
        // Split the interior vertex (1, 1, 0) = id 4 into two very close vertices.
        const int twin = addPoint(m, Vec3(1.0, 1.02, 0), 0);
        // Triangles of 4 on the upper side (y > 1) now use the twin, with a sliver between.
        std::vector<OutputTriangle> tris;
        for (OutputTriangle t : m.triangles) {
            if (t.surface == 0 && cornerIndex(t, 4) >= 0) {
                double cy = 0;
                for (int v : t.v)
                    cy += m.points[v].position.y();
                if (cy / 3.0 > 1.0)
                    t.v[cornerIndex(t, 4)] = twin;
            }
            tris.push_back(t);
        }
        // Close the gap along the horizontal line through (0,1)-(1,1)-(2,1).
        tris.push_back({{3, 4, twin}, 0});
        tris.push_back({{4, 5, twin}, 0});
        m.triangles = tris;
        EditableSoup soup(m);
        SimplificationLedger ledger;
        removeDegenerateTriangles(soup, Model{}, CleanupParams{}, ledger);
        const OutputMesh out = soup.result();
        QCOMPARE(out.points.size(), m.points.size() - 1);
        QVERIFY(contactSealed(out));
        QVERIFY(std::abs(totalArea(out, 0) - 4.0) < 1e-12);
        for (const OutputTriangle &t : out.triangles) {
            const Vec3 &a = out.points[t.v[0]].position, &b = out.points[t.v[1]].position,
                       &c = out.points[t.v[2]].position;
            QVERIFY((b - a).cross(c - a).norm() > 1e-3);
        }
    }

    void flipsImproveQuality()
    {
        // A quad split along its long diagonal gets the short one.
        OutputMesh m;
        for (const Vec3 &p : {Vec3(0, 0, 0), Vec3(4, -0.5, 0), Vec3(8, 0, 0), Vec3(4, 0.5, 0)})
            addPoint(m, p, 0);
        m.triangles.push_back({{0, 1, 2}, 0});
        m.triangles.push_back({{0, 2, 3}, 0});
        EditableSoup soup(m);
        QCOMPARE(improveByFlips(soup), 1);
        const OutputMesh out = soup.result();
        std::set<std::pair<int, int>> edges;
        for (const auto &[e, use] : edgeUse(out))
            edges.insert(e);
        QVERIFY(edges.count({1, 3}) == 1);
        QVERIFY(edges.count({0, 2}) == 0);
        for (const OutputTriangle &t : out.triangles) // orientation kept (+z)
            QVERIFY((out.points[t.v[1]].position - out.points[t.v[0]].position)
                        .cross(out.points[t.v[2]].position - out.points[t.v[0]].position)
                        .z()
                    > 0);
    }
};

QTEST_GUILESS_MAIN(TestMeshCleanup)
#include "test_mesh_cleanup.moc"
