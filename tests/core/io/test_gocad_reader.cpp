// Gocad .ml / .ts reading on small files written in code (formats.md §1.1–1.6, pitfalls §1.9).
#include "io/gocad_reader.h"

#include <QtTest>

#include <sstream>
#include <string>

using namespace stratamesh;

namespace {

Model readText(const std::string &text, const std::string &name = "test.ml")
{
    std::istringstream in(text);
    return readGocad(in, name);
}

std::string toCrlf(const std::string &text)
{
    std::string out;
    for (char c : text) {
        if (c == '\n')
            out += '\r';
        out += c;
    }
    return out;
}

struct ModelOptions {
    bool swapHorizonFaces = false; // body TFACEs of "horizon" written in the other order
    bool reverseFaultKey = false;  // key triangle of TFACE 3 written with the opposite cycle
};

// Two TSURFs: "horizon" (two TFACEs, the second sharing a border through ATOMs) and the quoted
// "fault one" (one TFACE); three regions with the Universe first; Depth frame.
std::string twoTSurfModel(const ModelOptions &o = {})
{
    const std::string faultKey = o.reverseFaultKey ? "  0.5 0 0\n  0.5 1 10\n  0.5 1 0\n"
                                                   : "  0.5 0 0\n  0.5 1 0\n  0.5 1 10\n";
    const std::string header = "GOCAD Model3d 1\n"
                               "HEADER {\n"
                               "name: \"two faces\"\n"
                               "*regions*visible: on\n"
                               "}\n"
                               "GOCAD_ORIGINAL_COORDINATE_SYSTEM\n"
                               "NAME \" gocad Local\"\n"
                               "AXIS_NAME \"X\" \"Y\" \"Z\"\n"
                               "ZPOSITIVE Depth\n"
                               "END_ORIGINAL_COORDINATE_SYSTEM\n"
                               "TSURF horizon\n"
                               "TSURF \"fault one\"\n"
                               "TFACE 1  top horizon\n"
                               "  0 0 5\n  1 0 5\n  1 1 5\n"
                               "TFACE 2  top horizon\n"
                               "  1 0 5\n  2 0 5\n  2 1 5\n"
                               "TFACE 3  fault \"fault one\"\n"
                               + faultKey
                               + "REGION 4  Universe\n"
                                 "  -1  +3  0\n"
                                 "REGION 5  \"upper block\"\n"
                                 "  +1  -2  0\n"
                                 "REGION 6  lower\n"
                                 "  +2  +3\n"
                                 "  -3  0\n"
                                 "SURFACE \"horizon feature\"\n"
                                 "  1  2  0\n"
                                 "LAYER L1\n"
                                 "  5  4  99  0\n"
                                 "LAYER L2\n"
                                 "  6  0\n"
                                 "FAULT_BLOCK B\n"
                                 "  5  6  0\n"
                                 "END\n";
    const std::string face1 = "TFACE\n"
                              "VRTX 10 0 0 5\n"
                              "VRTX 11 1 0 5 CNXYZ\n"
                              "PVRTX 12 1 1 5 7.5 CNXYZ\n"
                              "VRTX 13 0 1 5\n"
                              "TRGL 10 11 12\n"
                              "TRGL 10 12 13\n";
    // Written first when swapped: the ATOMs then refer to vertices of a later face, so the
    // swapped body defines its own copies instead.
    const std::string face2 = o.swapHorizonFaces ? "TFACE\n"
                                                   "VRTX 14 1 0 5\n"
                                                   "VRTX 15 1 1 5\n"
                                                   "VRTX 16 2 0 5\n"
                                                   "VRTX 17 2 1 5\n"
                                                   "TRGL 14 16 17\n"
                                                   "TRGL 14 17 15\n"
                                                 : "TFACE\n"
                                                   "ATOM 14 11\n"
                                                   "ATOM 15 12\n"
                                                   "VRTX 16 2 0 5\n"
                                                   "VRTX 17 2 1 5\n"
                                                   "TRGL 14 16 17\n"
                                                   "TRGL 14 17 15\n";
    const std::string horizon = "GOCAD TSurf 1\n"
                                "HEADER {\n"
                                "name_in_model_list: horizon\n"
                                "name: horizon\n"
                                "}\n"
                                "GOCAD_ORIGINAL_COORDINATE_SYSTEM\n"
                                "ZPOSITIVE Depth\n"
                                "END_ORIGINAL_COORDINATE_SYSTEM\n"
                                "PROPERTIES p\n"
                                "ESIZES 1\n"
                                "PROPERTY_CLASS_HEADER Z {\n"
                                "is_z: on\n"
                                "}\n"
                                + (o.swapHorizonFaces ? face2 + face1 : face1 + face2)
                                + "BSTONE 10\n"
                                  "BORDER 18 10 11\n"
                                  "END\n";
    const std::string fault = "GOCAD TSurf 1\n"
                              "HEADER {name:fault one}\n"
                              "GOCAD_ORIGINAL_COORDINATE_SYSTEM\n"
                              "ZPOSITIVE Depth\n"
                              "END_ORIGINAL_COORDINATE_SYSTEM\n"
                              "GEOLOGICAL_FEATURE F1\n"
                              "GEOLOGICAL_TYPE boundary\n"
                              "TFACE\n"
                              "VRTX 1 0.5 0 0\n"
                              "VRTX 2 0.5 1 0\n"
                              "VRTX 3 0.5 1 10\n"
                              "VRTX 4 0.5 0 10\n"
                              "TRGL 1 2 3\n"
                              "TRGL 1 3 4\n"
                              "END\n";
    return header + horizon + fault;
}

bool hasVertexAt(const Surface &s, const Vec3 &p)
{
    for (const Vec3 &v : s.vertices)
        if (v == p)
            return true;
    return false;
}

} // namespace

class TestGocadReader : public QObject {
    Q_OBJECT

private slots:
    void readsModel3dSurfaces()
    {
        const Model m = readText(twoTSurfModel());
        QCOMPARE(m.name, std::string("two faces"));
        QVERIFY(m.zPositiveDepth);
        QCOMPARE(m.surfaces.size(), std::size_t(3));
        QCOMPARE(m.surfaces[0].name, std::string("horizon_1"));
        QCOMPARE(m.surfaces[1].name, std::string("horizon_2"));
        QCOMPARE(m.surfaces[2].name, std::string("fault one"));
        // No GEOLOGICAL_FEATURE in the horizon body: the header SURFACE group names it.
        QCOMPARE(m.surfaces[0].featureName, std::string("horizon feature"));
        QCOMPARE(m.surfaces[2].featureName, std::string("F1"));
        // The header TFACE type wins over the body GEOLOGICAL_TYPE.
        QCOMPARE(m.surfaces[0].type, FeatureType::Horizon);
        QCOMPARE(m.surfaces[2].type, FeatureType::Fault);
        QCOMPARE(m.surfaces[1].sourceObject, std::string("horizon"));
        QCOMPARE(m.surfaces[2].sourceObject, std::string("fault one"));
        QCOMPARE(m.triangleCount(), std::size_t(6));
    }

    void keepsLocalVerticesAndTriangleOrder()
    {
        const Model m = readText(twoTSurfModel());
        const Surface &s0 = m.surfaces[0];
        QCOMPARE(s0.vertices.size(), std::size_t(4));
        QCOMPARE(s0.vertices[1], Vec3(1, 0, -5)); // Depth: z negated
        QCOMPARE(s0.vertices[2], Vec3(1, 1, -5)); // PVRTX property and flag ignored
        QCOMPARE(s0.triangles[0], (Triangle{0, 1, 2}));
        QCOMPARE(s0.triangles[1], (Triangle{0, 2, 3}));
        // ATOMs into the earlier TFACE become local vertices at the referenced positions.
        const Surface &s1 = m.surfaces[1];
        QCOMPARE(s1.vertices.size(), std::size_t(4));
        QCOMPARE(s1.vertices[0], Vec3(1, 0, -5));
        QCOMPARE(s1.vertices[1], Vec3(1, 1, -5));
        QCOMPARE(s1.vertices[2], Vec3(2, 0, -5));
        QCOMPARE(s1.triangles[0], (Triangle{0, 2, 3}));
        QCOMPARE(s1.triangles[1], (Triangle{0, 3, 1}));
        QCOMPARE(m.surfaces[2].vertices[2], Vec3(0.5, 1, -10));
    }

    void readsRegionsUniverseAndLayers()
    {
        const Model m = readText(twoTSurfModel());
        QCOMPARE(m.universe, (std::vector<RegionSide>{{0, false}, {2, true}}));
        QCOMPARE(m.regions.size(), std::size_t(2));
        QCOMPARE(m.regions[0].name, std::string("upper block"));
        QCOMPARE(m.regions[0].boundaries, (std::vector<RegionSide>{{0, true}, {1, false}}));
        QCOMPARE(m.regions[1].name, std::string("lower"));
        QCOMPARE(m.regions[1].boundaries,
                 (std::vector<RegionSide>{{1, true}, {2, true}, {2, false}}));
        // LAYER lists REGION ids: the Universe (4) and an unknown id (99) are ignored.
        QCOMPARE(m.layers.size(), std::size_t(2));
        QCOMPARE(m.layers[0].name, std::string("L1"));
        QCOMPARE(m.layers[0].regions, std::vector<int>{0});
        QCOMPARE(m.layers[1].regions, std::vector<int>{1});
    }

    void matchesReorderedFacesByKeyTriangle()
    {
        ModelOptions o;
        o.swapHorizonFaces = true;
        const Model m = readText(twoTSurfModel(o));
        // Surface 0 is still header TFACE 1, whose key triangle has (0,0,5) in file coordinates.
        QVERIFY(hasVertexAt(m.surfaces[0], Vec3(0, 0, -5)));
        QVERIFY(!hasVertexAt(m.surfaces[0], Vec3(2, 0, -5)));
        QVERIFY(hasVertexAt(m.surfaces[1], Vec3(2, 0, -5)));
        QCOMPARE(m.regions[0].boundaries, (std::vector<RegionSide>{{0, true}, {1, false}}));
    }

    void reversedKeyTriangleSwapsSides()
    {
        ModelOptions o;
        o.reverseFaultKey = true;
        const Model m = readText(twoTSurfModel(o));
        // The file's signs for TFACE 3 refer to its key triangle, opposite to the stored TRGLs.
        QCOMPARE(m.universe, (std::vector<RegionSide>{{0, false}, {2, false}}));
        QCOMPARE(m.regions[1].boundaries,
                 (std::vector<RegionSide>{{1, true}, {2, false}, {2, true}}));
        QCOMPARE(m.surfaces[2].triangles[0], (Triangle{0, 1, 2})); // triangles untouched
    }

    void crlfGivesTheSameModel()
    {
        const Model lf = readText(twoTSurfModel());
        const Model crlf = readText(toCrlf(twoTSurfModel()));
        QCOMPARE(crlf.name, lf.name);
        QCOMPARE(crlf.surfaces.size(), lf.surfaces.size());
        for (std::size_t i = 0; i < lf.surfaces.size(); ++i) {
            QCOMPARE(crlf.surfaces[i].name, lf.surfaces[i].name);
            QCOMPARE(crlf.surfaces[i].featureName, lf.surfaces[i].featureName);
            QCOMPARE(crlf.surfaces[i].vertices, lf.surfaces[i].vertices);
            QCOMPARE(crlf.surfaces[i].triangles, lf.surfaces[i].triangles);
        }
        QCOMPARE(crlf.regions[0].name, std::string("upper block"));
        QCOMPARE(crlf.regions[1].boundaries, lf.regions[1].boundaries);
    }

    void elevationKeepsZ()
    {
        std::string text = twoTSurfModel();
        for (std::size_t p = text.find("Depth"); p != std::string::npos; p = text.find("Depth"))
            text.replace(p, 5, "Elevation");
        const Model m = readText(text);
        QVERIFY(!m.zPositiveDepth);
        QCOMPARE(m.surfaces[0].vertices[1], Vec3(1, 0, 5));
        QCOMPARE(m.surfaces[2].vertices[2], Vec3(0.5, 1, 10));
    }

    void atomInSameFaceMakesACut()
    {
        const Model m = readText("GOCAD TSurf 1\n"
                                 "HEADER {\nname:cut\n}\n"
                                 "TFACE\n"
                                 "VRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 1 1 0\nVRTX 4 0 1 0\n"
                                 "ATOM 5 3\n"
                                 "TRGL 1 2 3\nTRGL 1 5 4\n"
                                 "TFACE\n"
                                 "ATOM 6 5\n" // an ATOM of an ATOM of face 1
                                 "VRTX 7 2 1 0\n"
                                 "TRGL 6 2 7\n" // 2 belongs to face 1: copied once
                                 "TRGL 2 6 7\n"
                                 "END\n",
                                 "cut.ts");
        QCOMPARE(m.surfaces.size(), std::size_t(2));
        const Surface &s = m.surfaces[0];
        QCOMPARE(s.vertices.size(), std::size_t(5));
        QCOMPARE(s.vertices[4], s.vertices[2]); // same point, distinct vertex
        QCOMPARE(s.triangles[1], (Triangle{0, 4, 3}));
        const Surface &t = m.surfaces[1];
        QCOMPARE(t.vertices.size(), std::size_t(3));
        QCOMPARE(t.vertices[0], Vec3(1, 1, 0));
        QCOMPARE(t.vertices[2], Vec3(1, 0, 0));
        QCOMPARE(t.triangles[0], (Triangle{0, 2, 1}));
        QCOMPARE(t.triangles[1], (Triangle{2, 0, 1}));
        QCOMPARE(s.name, std::string("cut_1"));
        QCOMPARE(t.name, std::string("cut_2"));
    }

    void idsNeedNotStartAtOne()
    {
        const Model m = readText("GOCAD TSurf 1\nHEADER {name:ids}\nTFACE\n"
                                 "VRTX 1000 0 0 0\nVRTX 0 1 0 0\nVRTX 7 0 1 0\nVRTX -3 1 1 0\n"
                                 "TRGL 1000 0 7\nTRGL 0 -3 7\nEND\n",
                                 "ids.ts");
        const Surface &s = m.surfaces[0];
        QCOMPARE(s.vertices[0], Vec3(0, 0, 0));
        QCOMPARE(s.vertices[3], Vec3(1, 1, 0));
        QCOMPARE(s.triangles[0], (Triangle{0, 1, 2}));
        QCOMPARE(s.triangles[1], (Triangle{1, 3, 2}));
    }

    void unusedVerticesAreDropped()
    {
        const Model m = readText("GOCAD TSurf 1\nHEADER {name:u}\nTFACE\n"
                                 "VRTX 1 0 0 0\nVRTX 2 9 9 9\nVRTX 3 1 0 0\nVRTX 4 0 1 0\n"
                                 "TRGL 1 3 4\nEND\n",
                                 "u.ts");
        QCOMPARE(m.surfaces[0].vertices.size(), std::size_t(3));
        QCOMPARE(m.surfaces[0].triangles[0], (Triangle{0, 1, 2}));
    }

    void tsFileWithSeveralObjects()
    {
        const std::string text =
            "# written by hand\n"
            "GOCAD PLine 1\nHEADER {name:line}\nILINE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\n"
            "SEG 1 2\nEND\n"
            "gocad TSURF 1\n"
            "HEADER {\nname:h\n}\n"
            "GEOLOGICAL_TYPE top\n"
            "STRATIGRAPHIC_POSITION x 1\n"
            "SOME_NEW_KEYWORD a b c\n"
            "\n"
            "TFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\n"
            "TFACE\nVRTX 4 5 0 0\nVRTX 5 6 0 0\nVRTX 6 5 1 0\nTRGL 4 5 6\nTRGL 6 5 4\n"
            "END\n"
            "GOCAD TSurf 1\n"
            "HEADER {\nname: \"my fault\"\n}\n"
            "GEOLOGICAL_FEATURE big_fault\n"
            "GEOLOGICAL_TYPE normal_fault\n"
            "VRTX 1 0 0 1\nVRTX 2 1 0 1\nVRTX 3 0 1 1\nTRGL 1 2 3\n" // no TFACE
            "END\n"
            "GOCAD TSurf 1\nHEADER {name:h_1}\n"
            "TFACE\nVRTX 1 0 0 2\nVRTX 2 1 0 2\nVRTX 3 0 1 2\nTRGL 1 2 3\nEND\n";
        const Model m = readText(text, "/some/dir/several.ts");
        QCOMPARE(m.name, std::string("several"));
        QVERIFY(m.regions.empty());
        QVERIFY(m.universe.empty());
        QCOMPARE(m.surfaces.size(), std::size_t(4));
        QCOMPARE(m.surfaces[0].name, std::string("h_1"));
        QCOMPARE(m.surfaces[1].name, std::string("h_2"));
        QCOMPARE(m.surfaces[1].triangles.size(), std::size_t(2));
        QCOMPARE(m.surfaces[0].type, FeatureType::Horizon);
        QCOMPARE(m.surfaces[0].featureName, std::string("h"));
        QCOMPARE(m.surfaces[2].name, std::string("my fault"));
        QCOMPARE(m.surfaces[2].featureName, std::string("big_fault"));
        QCOMPARE(m.surfaces[2].type, FeatureType::Fault);
        QCOMPARE(m.surfaces[2].vertices[0], Vec3(0, 0, 1));
        // An object named like a patch of "h": the surface name is made unique.
        QCOMPARE(m.surfaces[3].name, std::string("h_1_2"));
        QCOMPARE(m.surfaces[3].sourceObject, std::string("h_1"));
        QCOMPARE(m.surfaces[3].type, FeatureType::Unknown);
    }

    void lonelyTSurfWithoutNameTakesTheFileStem()
    {
        const Model m =
            readText("GOCAD TSurf 1\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n",
                     "C:\\data\\lonely.ts");
        QCOMPARE(m.surfaces[0].name, std::string("lonely"));
        QCOMPARE(m.surfaces[0].featureName, std::string("lonely"));
    }
};

QTEST_GUILESS_MAIN(TestGocadReader)
#include "test_gocad_reader.moc"
