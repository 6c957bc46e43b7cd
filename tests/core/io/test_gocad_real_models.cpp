// The real Gocad models load with the counts the files themselves declare (header TFACE lines,
// TRGL lines), the counts of design.md §4, and region volumes that close (formats.md §0 fact 1).
#include "io/model_reader.h"
#include "support/test_data.h"

#include <Eigen/Geometry>

#include <QFile>
#include <QtTest>

#include <set>

using namespace stratamesh;

namespace {

struct FileCounts {
    int headerFaces = 0; // "TFACE <id> ..." lines (body TFACE lines carry no id)
    int trglLines = 0;
};

// Counted from the text, independently of the reader.
FileCounts countLines(const QString &path)
{
    FileCounts c;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return c;
    while (!f.atEnd()) {
        const QList<QByteArray> tokens = f.readLine().simplified().split(' ');
        if (tokens.size() >= 2 && tokens[0] == "TFACE")
            ++c.headerFaces;
        else if (!tokens.isEmpty() && tokens[0] == "TRGL")
            ++c.trglLines;
    }
    return c;
}

// Signed volume enclosed by a surface, divergence theorem over its triangles.
double signedVolume(const Surface &s)
{
    double v = 0.0;
    for (const Triangle &t : s.triangles)
        v += s.vertices[t[0]].dot(s.vertices[t[1]].cross(s.vertices[t[2]])) / 6.0;
    return v;
}

// A region lies on the side its positive surfaces' normals point to: those normals point
// inwards, so they count negatively in the outward flux.
double regionVolume(const std::vector<RegionSide> &sides, const std::vector<double> &vol)
{
    double v = 0.0;
    for (const RegionSide &s : sides)
        v += s.positive ? -vol[s.surface] : vol[s.surface];
    return v;
}

void checkWellFormed(const Model &m)
{
    std::set<std::string> names;
    for (const Surface &s : m.surfaces) {
        QVERIFY2(names.insert(s.name).second, s.name.c_str());
        QVERIFY(!s.triangles.empty());
        for (const Vec3 &p : s.vertices)
            QVERIFY(p.allFinite());
        for (const Triangle &t : s.triangles)
            for (int v : t)
                QVERIFY(v >= 0 && v < int(s.vertices.size()));
    }
    for (const Region &r : m.regions)
        for (const RegionSide &side : r.boundaries)
            QVERIFY(side.surface >= 0 && side.surface < int(m.surfaces.size()));
}

} // namespace

class TestGocadRealModels : public QObject {
    Q_OBJECT

private slots:
    void loadsModelAs_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("surfaces");
        QTest::addColumn<int>("triangles");
        QTest::addColumn<int>("regions");
        // Surfaces = header TFACEs; triangles per design.md §4; regions per thesis Table 3.1.
        QTest::newRow("modelA1") << "modelA1.ml" << 21 << 7932 << 4;
        QTest::newRow("modelA2") << "modelA2.ml" << 61 << 16346 << 12;
        QTest::newRow("modelA5") << "modelA5.ml" << 64 << 14553 << 12;
    }

    void loadsModelAs()
    {
        QFETCH(QString, file);
        QFETCH(int, surfaces);
        QFETCH(int, triangles);
        QFETCH(int, regions);
        STRATAMESH_REQUIRE_DATA(path, file);
        const FileCounts counts = countLines(path);
        const Model m = readModel(path.toStdString());
        QCOMPARE(int(m.surfaces.size()), counts.headerFaces);
        QCOMPARE(int(m.triangleCount()), counts.trglLines);
        QCOMPARE(int(m.surfaces.size()), surfaces);
        QCOMPARE(int(m.triangleCount()), triangles);
        QCOMPARE(int(m.regions.size()), regions);
        QVERIFY(m.zPositiveDepth);
        QVERIFY(!m.universe.empty());
        QVERIFY(!m.hasTopology());
        checkWellFormed(m);
    }

    // With the z-flip and the side rule every region has a positive volume, and they add up to
    // the box shared by A1/A2/A5 (7.76229e11, formats.md §1.6); the Universe is its negative.
    void regionVolumesClose_data() { loadsModelAs_data(); }
    void regionVolumesClose()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        const Model m = readModel(path.toStdString());
        std::vector<double> vol;
        for (const Surface &s : m.surfaces)
            vol.push_back(signedVolume(s));
        double total = 0.0;
        for (const Region &r : m.regions) {
            const double v = regionVolume(r.boundaries, vol);
            QVERIFY2(v > 0.0, r.name.c_str());
            total += v;
        }
        QVERIFY(qAbs(total - 7.76229e11) < 1e-5 * 7.76229e11);
        QVERIFY(qAbs(regionVolume(m.universe, vol) + total) < 1e-6 * total);
    }

    void loadsCubes()
    {
        STRATAMESH_REQUIRE_DATA(split, "split_cube.ml");
        STRATAMESH_REQUIRE_DATA(nonSplit, "non_split_cube.ml");
        STRATAMESH_REQUIRE_DATA(notSealed, "not_sealed_cube.ml");

        const Model s = readModel(split.toStdString());
        QCOMPARE(s.surfaces.size(), std::size_t(3));
        QCOMPARE(s.triangleCount(), std::size_t(22));
        QCOMPARE(s.regions.size(), std::size_t(2));
        QCOMPARE(s.surfaces[0].name, std::string("box_1"));
        QCOMPARE(s.surfaces[2].name, std::string("horizon"));
        QCOMPARE(s.surfaces[0].type, FeatureType::Boundary);
        QCOMPARE(s.surfaces[2].type, FeatureType::Horizon);
        // The second box face uses ATOMs of the first: its own 8 vertices.
        QCOMPARE(s.surfaces[1].vertices.size(), std::size_t(8));
        checkWellFormed(s);

        const Model n = readModel(nonSplit.toStdString());
        QCOMPARE(n.surfaces.size(), std::size_t(2));
        QCOMPARE(n.triangleCount(), std::size_t(22));
        QCOMPARE(n.regions.size(), std::size_t(1));
        // "+2 -2": the partial horizon hangs inside the region.
        QCOMPARE(n.regions[0].boundaries,
                 (std::vector<RegionSide>{{0, true}, {1, true}, {1, false}}));
        // Same-face ATOMs 13 and 14 cut the box: 14 vertices at 12 distinct points.
        QCOMPARE(n.surfaces[0].vertices.size(), std::size_t(14));
        checkWellFormed(n);

        const Model u = readModel(notSealed.toStdString());
        QCOMPARE(u.surfaces.size(), std::size_t(6));
        QCOMPARE(u.triangleCount(), std::size_t(12));
        QVERIFY(u.regions.empty());
        QCOMPARE(u.universe.size(), std::size_t(12));
        QVERIFY(!u.zPositiveDepth);
        checkWellFormed(u);
    }
};

QTEST_GUILESS_MAIN(TestGocadRealModels)
#include "test_gocad_real_models.moc"
