// Gocad Model3d and TSurf output read back by the Gocad reader: names, features, types, exact
// coordinates, region sides (positive volumes), the Universe with the opposite signs, ZPOSITIVE
// Depth honoured both ways, BSTONE/BORDER from the topology, clear errors.
#include "common/error.h"
#include "io/gocad_writer.h"
#include "io/model_reader.h"
#include "model/region_volume.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "test_roundtrip_meshes.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <set>

using namespace stratamesh;

namespace {

Model faultedBox()
{
    LayeredBoxParams p;
    p.fault = true;
    p.faultThrow = 40;
    p.foldAmplitude = 30;
    p.edgeLength = 120;
    p.size = Vec3(1000.0 + 1.0 / 3.0, 600, 400); // digits a float would lose
    return recoverTopology(layeredBox(p));
}

std::set<std::pair<int, bool>> asSet(const std::vector<RegionSide> &sides)
{
    std::set<std::pair<int, bool>> out;
    for (const RegionSide &s : sides)
        out.insert({s.surface, s.positive});
    return out;
}

// The sides no region claims: what the Universe must list.
std::set<std::pair<int, bool>> expectedUniverse(const Model &m)
{
    std::set<std::pair<int, bool>> claimed, out;
    for (const Region &r : m.regions)
        for (const RegionSide &s : r.boundaries)
            claimed.insert({s.surface, s.positive});
    for (int s = 0; s < int(m.surfaces.size()); ++s)
        for (bool positive : {true, false})
            if (!claimed.count({s, positive}))
                out.insert({s, positive});
    return out;
}

QList<QByteArray> linesStartingWith(const QString &path, const QByteArray &prefix)
{
    QFile f(path);
    QList<QByteArray> out;
    if (!f.open(QIODevice::ReadOnly))
        return out;
    while (!f.atEnd()) {
        const QByteArray line = f.readLine();
        if (line.startsWith(prefix))
            out << line.trimmed();
    }
    return out;
}

} // namespace

class TestGocadWriter : public QObject {
    Q_OBJECT

private slots:
    void model3dRoundTrip_data()
    {
        QTest::addColumn<bool>("depth");
        QTest::newRow("elevation") << false;
        QTest::newRow("depth") << true;
    }
    void model3dRoundTrip()
    {
        QFETCH(bool, depth);
        Model model = faultedBox();
        model.zPositiveDepth = depth;
        QTemporaryDir dir;
        const QString path = dir.filePath("box.ml");
        writeGocadModel3d(model, path.toStdString());
        const Model back = readModel(path.toStdString());
        const std::string diff = test::compareModels(model, back);
        QVERIFY2(diff.empty(), diff.c_str());
        QCOMPARE(back.zPositiveDepth, depth);
        QCOMPARE(back.name, model.name);
        QCOMPARE(int(back.layers.size()), int(model.layers.size()));
        // Signs are right: every region encloses a positive volume, the Universe the opposite.
        double total = 0;
        for (double v : regionVolumes(back)) {
            QVERIFY(v > 0);
            total += v;
        }
        QVERIFY(std::abs(universeVolume(back) + total) < 1e-6 * total);
        QCOMPARE(asSet(back.universe), expectedUniverse(model));
    }

    void depthNegatesZInTheFile()
    {
        Model model;
        model.name = "one";
        model.zPositiveDepth = true;
        Surface s;
        s.name = s.featureName = s.sourceObject = "h";
        s.type = FeatureType::Horizon;
        s.vertices = {{0, 0, 10}, {1, 0, 10.5}, {0, 1, -3}};
        s.triangles = {{0, 1, 2}};
        model.surfaces.push_back(s);
        QTemporaryDir dir;
        const QString path = dir.filePath("one.ts");
        writeGocadTSurf(model, path.toStdString());
        QCOMPARE(linesStartingWith(path, "VRTX"),
                 (QList<QByteArray>{"VRTX 1 0 0 -10", "VRTX 2 1 0 -10.5", "VRTX 3 0 1 3"}));
        QCOMPARE(linesStartingWith(path, "ZPOSITIVE"), QList<QByteArray>{"ZPOSITIVE Depth"});
        const Model back = readModel(path.toStdString());
        QCOMPARE(back.surfaces.at(0).vertices, s.vertices);
        QVERIFY(back.zPositiveDepth);
    }

    void universeHasTheOppositeSigns()
    {
        const Model model = faultedBox();
        QTemporaryDir dir;
        const QString path = dir.filePath("box.ml");
        writeGocadModel3d(model, path.toStdString());
        // Box surfaces bound one region each: the Universe lists each once, with the other sign.
        const Model back = readModel(path.toStdString());
        for (const RegionSide &u : back.universe) {
            int sameSign = 0, otherSign = 0;
            for (const Region &r : back.regions)
                for (const RegionSide &s : r.boundaries)
                    if (s.surface == u.surface)
                        (s.positive == u.positive ? sameSign : otherSign)++;
            QCOMPARE(sameSign, 0);
            QCOMPARE(otherSign, 1);
            QCOMPARE(back.surfaces[u.surface].type, FeatureType::Boundary);
        }
        QVERIFY(!back.universe.empty());
    }

    void bordersComeFromTheTopology()
    {
        const Model model = faultedBox();
        QVERIFY(!model.lines.empty());
        QTemporaryDir dir;
        const QString path = dir.filePath("box.ml");
        writeGocadModel3d(model, path.toStdString());
        const QList<QByteArray> borders = linesStartingWith(path, "BORDER ");
        const QList<QByteArray> stones = linesStartingWith(path, "BSTONE ");
        // Every line bounds at least one face; each face side of a line gets one BORDER.
        std::size_t surfaceLines = 0;
        for (const Surface &s : model.surfaces)
            surfaceLines += s.lines.size();
        QVERIFY(std::size_t(borders.size()) >= surfaceLines);
        QVERIFY(!stones.isEmpty());
        // Without topology there are none.
        Model plain = model;
        plain.vertices.clear();
        plain.surfaceVertexToGlobal.clear();
        writeGocadModel3d(plain, path.toStdString());
        QVERIFY(linesStartingWith(path, "BORDER ").isEmpty());
    }

    void tsurfOneAndAll()
    {
        const Model model = faultedBox();
        QTemporaryDir dir;
        const QString one = dir.filePath("one.ts"), all = dir.filePath("all.ts");
        writeGocadTSurf(model, one.toStdString(), 3);
        const Model single = readModel(one.toStdString());
        QCOMPARE(int(single.surfaces.size()), 1);
        QCOMPARE(single.surfaces[0].name, model.surfaces[3].name);
        QCOMPARE(single.surfaces[0].vertices, model.surfaces[3].vertices);
        QCOMPARE(single.surfaces[0].triangles, model.surfaces[3].triangles);
        writeGocadTSurf(model, all.toStdString());
        test::ModelCompare c;
        c.regions = false; // a TSurf file has no region
        const std::string diff = test::compareModels(model, readModel(all.toStdString()), c);
        QVERIFY2(diff.empty(), diff.c_str());
    }

    void surfaceGroupsKeepNames()
    {
        // Patches of one object named like a reader names them share one TSurf; others get their
        // own.
        Model model;
        model.name = "groups";
        for (const char *name : {"fault_1", "fault_2", "lonely"}) {
            Surface s;
            s.name = name;
            s.sourceObject = std::string(name).rfind("fault", 0) == 0 ? "fault" : "other";
            s.featureName = "F";
            s.type = std::string(name) == "lonely" ? FeatureType::Unknown : FeatureType::Fault;
            s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
            s.triangles = {{0, 1, 2}};
            model.surfaces.push_back(s);
        }
        QTemporaryDir dir;
        const QString path = dir.filePath("g.ml");
        writeGocadModel3d(model, path.toStdString());
        QCOMPARE(linesStartingWith(path, "TSURF "),
                 (QList<QByteArray>{"TSURF fault", "TSURF lonely"}));
        test::ModelCompare c;
        const std::string diff = test::compareModels(model, readModel(path.toStdString()), c);
        QVERIFY2(diff.empty(), diff.c_str()); // including type Unknown, not read back as a horizon
    }

    void quotedNames()
    {
        Model model = faultedBox();
        model.surfaces[0].name = "top of box";
        model.regions[0].name = "upper block";
        QTemporaryDir dir;
        const QString path = dir.filePath("q.ml");
        writeGocadModel3d(model, path.toStdString());
        const std::string diff = test::compareModels(model, readModel(path.toStdString()));
        QVERIFY2(diff.empty(), diff.c_str());
    }

    void errorsAreClear()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.ml");
        QVERIFY_THROWS_EXCEPTION(InputError, writeGocadModel3d(Model{}, path.toStdString()));
        Model model = faultedBox();
        model.surfaces[2].triangles.clear();
        try {
            writeGocadModel3d(model, path.toStdString());
            QFAIL("wrote an empty surface");
        } catch (const InputError &e) {
            QVERIFY2(std::string(e.what()).find(model.surfaces[2].name) != std::string::npos,
                     e.what());
        }
        QVERIFY(!QFile::exists(path));
        QVERIFY_THROWS_EXCEPTION(InputError,
                                 writeGocadTSurf(faultedBox(), path.toStdString(), 999));
    }
};

QTEST_GUILESS_MAIN(TestGocadWriter)
#include "test_gocad_writer.moc"
