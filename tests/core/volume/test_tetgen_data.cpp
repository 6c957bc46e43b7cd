// TetGen comparison meshes of the real model A1 and of its remesh at 1000 sites: every region gets
// tets carrying its id, and per region the tet volumes sum to the B-Rep volume (1e-6 relative).
#include "io/model_reader.h"
#include "model/region_volume.h"
#include "model/topology.h"
#include "remesh/surface_remesher.h"
#include "support/test_data.h"
#include "volume/region_tets.h"
#include "volume/tet_quality.h"
#include "volume/tetgen_runner.h"

#include <QtTest>

using namespace stratamesh;

namespace {

void checkRegions(const Model &model, const TetgenResult &r)
{
    QVERIFY2(r.outcome == TetgenOutcome::Ok, r.message.c_str());
    QCOMPARE(r.tetsWithoutRegion, std::size_t(0));
    const std::vector<double> brep = regionVolumes(model);
    const std::vector<RegionTets> tets = regionTets(r.mesh);
    QCOMPARE(tets.size(), model.regions.size());
    for (std::size_t k = 0; k < tets.size(); ++k) {
        QVERIFY2(tets[k].tets > 0, model.regions[k].name.c_str());
        const double error = std::abs(tets[k].volume - brep[k]) / brep[k];
        QVERIFY2(error <= 1e-6, qPrintable(QStringLiteral("%1: tets %2, B-Rep %3")
                                               .arg(QString::fromStdString(model.regions[k].name))
                                               .arg(tets[k].volume, 0, 'g', 17)
                                               .arg(brep[k], 0, 'g', 17)));
    }
    const VolumeQualityStatistics q = volumeQuality(r.mesh);
    qInfo("%s: %zu tets, %zu points, dihedral %.4g-%.4g deg, %zu slivers, %.2f s, %zu tets by "
          "centroid",
          model.name.c_str(), q.tets, r.mesh.points.size(), q.minDihedralDeg, q.maxDihedralDeg,
          q.slivers, r.seconds, r.tetsLocatedByCentroid);
}

} // namespace

class TestTetgenData : public QObject {
    Q_OBJECT

private slots:
    void modelA1()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        const Model m = recoverTopology(readModel(path.toStdString()));
        TetgenParams p;
        p.timeLimitSeconds = 60;
        checkRegions(m, runTetgen(m, p));
    }

    void modelA1Remeshed()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        const Model input = recoverTopology(readModel(path.toStdString()));
        RemeshParams rp;
        rp.sites = 1000;
        rp.seed = 1;
        const Model remeshed = recoverTopology(remeshModel(input, rp).model);
        TetgenParams p;
        p.timeLimitSeconds = 60;
        checkRegions(remeshed, runTetgen(remeshed, p));
    }
};

QTEST_GUILESS_MAIN(TestTetgenData)
#include "test_tetgen_data.moc"
