// The mixed-mesh checker: a hand-built valid mesh passes with its hand-computed region volumes,
// and each single defect (inverted cell, warped or twisted quad, missing cell, non-conformal
// split, overlap, untagged cell, missing interface, wrong volume) is found and located.
#include "common/error.h"
#include "hybrid/cell_quality.h"
#include "hybrid/mixed_mesh_validity.h"
#include "mixed_fixture.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace stratamesh;

namespace {

MixedMeshCheckParams withVolumes()
{
    MixedMeshCheckParams p;
    p.regionVolumes = {test::fixtureCoreVolume(), test::fixtureCapVolume()};
    return p;
}

bool lists(const MixedMeshValidity &v, int cell)
{
    return std::binary_search(v.invalidCells.begin(), v.invalidCells.end(), cell);
}

} // namespace

class TestMixedMeshValidity : public QObject {
    Q_OBJECT

private slots:
    void fixtureIsValid()
    {
        const VolumeMesh m = test::mixedFixture();
        const MixedMeshValidity v = checkMixedMesh(m, withVolumes());
        QVERIFY2(v.valid(), v.firstProblem.c_str());
        QVERIFY(v.invalidCells.empty());
        QVERIFY(std::abs(v.regionVolumes[0] - test::fixtureCoreVolume()) < 1e-12);
        QVERIFY(std::abs(v.regionVolumes[1] - test::fixtureCapVolume()) < 1e-12);
        QVERIFY(v.maxQuadWarpDegrees < 1e-4);
    }

    void invertedCellIsFound()
    {
        VolumeMesh m = test::mixedFixture();
        std::swap(m.cells[4].nodes[0], m.cells[4].nodes[1]);
        const MixedMeshValidity v = checkMixedMesh(m);
        QVERIFY(!v.valid());
        QCOMPARE(v.nonPositiveCells, std::size_t(1));
        QVERIFY(lists(v, 4));
    }

    void warpedQuadIsFound()
    {
        VolumeMesh m = test::mixedFixture();
        m.points[4] = {1.0, 0.2, 1.0}; // moves one corner of the y=0 quad out of its plane
        MixedMeshCheckParams p;
        p.maxQuadWarpDegrees = 5.0;
        const MixedMeshValidity v = checkMixedMesh(m, p);
        QVERIFY(v.warpedQuads >= 1);
        QVERIFY(v.maxQuadWarpDegrees > 5.0 && v.maxQuadWarpDegrees < 90.0);
        QVERIFY(lists(v, 0) && lists(v, 1));
        p.maxQuadWarpDegrees = 89.0; // the same mesh within a loose bound
        QCOMPARE(checkMixedMesh(m, p).warpedQuads, std::size_t(0));
    }

    void twistedQuadWarpIsAbove90()
    {
        const double bowTie = quadWarpDegrees({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0});
        QVERIFY(bowTie > 90.0);
        const double square = quadWarpDegrees({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
        QVERIFY(square < 1e-9);
    }

    void missingCellLeavesAQuadOnTheBoundary()
    {
        VolumeMesh m = test::mixedFixture();
        m.cells.erase(m.cells.begin() + 1);
        m.cellRegion.erase(m.cellRegion.begin() + 1);
        const MixedMeshValidity v = checkMixedMesh(m);
        QCOMPARE(v.boundaryOffSurface, std::size_t(1)); // the prism's bare quad
        QCOMPARE(v.surfaceWithoutCell, std::size_t(4)); // the pyramid's four triangles
        QVERIFY(lists(v, 0));
    }

    void tetsOnHalfAQuadAreNonConformal()
    {
        VolumeMesh m = test::mixedFixture();
        // The pyramid on quad 0-1-4-3 becomes two tets split along 0-4: same volume, but the
        // prism still has the whole quad.
        m.cells[1] = Cell::tet(0, 1, 4, 6);
        m.cells.push_back(Cell::tet(0, 4, 3, 6));
        m.cellRegion.push_back(0);
        const MixedMeshValidity v = checkMixedMesh(m, withVolumes());
        QCOMPARE(v.nonConformalFaces, std::size_t(2));
        QCOMPARE(v.regionsWithWrongVolume, std::size_t(0));
        QVERIFY(lists(v, 1) && lists(v, 5));
    }

    void duplicatedCellOverlaps()
    {
        VolumeMesh m = test::mixedFixture();
        m.cells.push_back(m.cells[4]);
        m.cellRegion.push_back(1);
        const MixedMeshValidity v = checkMixedMesh(m, withVolumes());
        QCOMPARE(v.sameSidedFaces, std::size_t(3));
        QCOMPARE(v.overSharedFaces, std::size_t(1)); // the interface: prism + two tets
        QCOMPARE(v.regionsWithWrongVolume, std::size_t(1));
        QVERIFY(lists(v, 4) && lists(v, 5));
    }

    void untaggedCellAndMissingInterface()
    {
        VolumeMesh m = test::mixedFixture();
        m.cellRegion[2] = -1;
        m.triangles.pop_back(); // the interface 3-4-5 between core and cap
        m.triangleSurface.pop_back();
        const MixedMeshValidity v = checkMixedMesh(m);
        QCOMPARE(v.cellsWithoutRegion, std::size_t(1));
        QCOMPARE(v.interfaceOffSurface, std::size_t(1));
        QVERIFY(lists(v, 2) && lists(v, 0) && lists(v, 4));
    }

    void wrongRegionVolumeIsFound()
    {
        MixedMeshCheckParams p = withVolumes();
        p.regionVolumes[1] *= 1.01;
        const MixedMeshValidity v = checkMixedMesh(test::mixedFixture(), p);
        QCOMPARE(v.regionsWithWrongVolume, std::size_t(1));
        QVERIFY(v.invalidCells.empty());
        p.regionVolumes.pop_back();
        QVERIFY_THROWS_EXCEPTION(InputError, checkMixedMesh(test::mixedFixture(), p));
    }

    void dihedralsOfReferenceCells()
    {
        VolumeMesh m;
        m.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}; // regular tet
        const DihedralRange tet = cellDihedrals(m, Cell::tet(0, 1, 2, 3));
        const double regular = std::acos(1.0 / 3.0) * 180.0 / M_PI; // 70.53
        QVERIFY(std::abs(tet.minDegrees - regular) < 1e-9);
        QVERIFY(std::abs(tet.maxDegrees - regular) < 1e-9);

        const VolumeMesh f = test::mixedFixture();
        const DihedralRange prism = cellDihedrals(f, f.cells[0]); // right-triangle prism
        QVERIFY(std::abs(prism.minDegrees - 45.0) < 1e-9);
        QVERIFY(std::abs(prism.maxDegrees - 90.0) < 1e-9);
        const DihedralRange pyramid = cellDihedrals(f, f.cells[1]); // apex 0.5 above a unit square
        QVERIFY(std::abs(pyramid.minDegrees - 45.0) < 1e-9);
        QVERIFY(std::abs(pyramid.maxDegrees - 120.0) < 1e-9);

        const auto byType = qualityByType(f);
        QCOMPARE(byType[0].cells, std::size_t(1));
        QCOMPARE(byType[1].cells, std::size_t(3));
        QCOMPARE(byType[2].cells, std::size_t(1));
        QCOMPARE(byType[0].slivers, std::size_t(0));
    }
};

QTEST_APPLESS_MAIN(TestMixedMeshValidity)
#include "test_mixed_mesh_validity.moc"
