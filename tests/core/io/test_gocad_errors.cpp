// Malformed Gocad input: every case must raise FileError naming the file, the right line and a
// cause — never crash, never return a model.
#include "common/error.h"
#include "io/gocad_reader.h"
#include "io/model_reader.h"

#include <QTemporaryDir>
#include <QtTest>

#include <initializer_list>
#include <sstream>
#include <string>

using namespace stratamesh;

namespace {

const std::string kFile = "bad_model.ml";

std::string lines(std::initializer_list<const char *> ls)
{
    std::string s;
    for (const char *l : ls)
        (s += l) += '\n';
    return s;
}

// A valid TSurf; line numbers in comments are those the error cases rely on.
std::string tsurf(const char *line4 = "VRTX 1 0 0 0", const char *line5 = "VRTX 2 1 0 0",
                  const char *line7 = "TRGL 1 2 3", const char *line8 = "END")
{
    return lines({"GOCAD TSurf 1",   // 1
                  "HEADER {name:s}", // 2
                  "TFACE",           // 3
                  line4,             // 4
                  line5,             // 5
                  "VRTX 3 0 1 0",    // 6
                  line7,             // 7
                  line8});           // 8
}

// Model3d header declaring TSURF s with one TFACE (key = the TSurf's triangle), lines 1-12.
std::string model3dHeader(const char *line11 = "  +1 0")
{
    return lines({"GOCAD Model3d 1",   // 1
                  "TSURF s",           // 2
                  "TFACE 1 top s",     // 3
                  "  0 0 0",           // 4
                  "  1 0 0",           // 5
                  "  0 1 0",           // 6
                  "REGION 2 Universe", // 7
                  "  -1 0",            // 8
                  "REGION 3 R",        // 9
                  "  +1",              // 10
                  line11,              // 11
                  "END"});             // 12
}

void expectError(const std::string &text, int line, const std::string &cause)
{
    std::istringstream in(text);
    try {
        readGocad(in, kFile);
    } catch (const FileError &e) {
        const std::string what = e.what();
        QVERIFY2(e.file() == kFile, what.c_str());
        QVERIFY2(e.line() == line,
                 (what + "  (expected line " + std::to_string(line) + ")").c_str());
        const std::string prefix =
            line > 0 ? kFile + ":" + std::to_string(line) + ": " : kFile + ": ";
        QVERIFY2(what.rfind(prefix, 0) == 0, what.c_str());
        QVERIFY2(what.find(cause) != std::string::npos,
                 (what + "  (expected: " + cause + ")").c_str());
        return;
    } catch (const std::exception &e) {
        QFAIL((std::string("not a FileError: ") + e.what()).c_str());
    }
    QFAIL("no error raised");
}

} // namespace

class TestGocadErrors : public QObject {
    Q_OBJECT

private slots:
    void validBaselinesLoad()
    {
        // The cases below differ from these files by one defect each.
        std::istringstream ts(tsurf());
        QCOMPARE(readGocad(ts, kFile).surfaces.size(), std::size_t(1));
        std::istringstream ml(model3dHeader() + tsurf());
        QCOMPARE(readGocad(ml, kFile).regions.size(), std::size_t(1));
    }

    void truncatedFile()
    {
        std::string text = tsurf();
        text.erase(text.find("TRGL"));
        expectError(text, 6, "file ends before the END of TSurf 's'");
    }

    void truncatedKeyTriangle()
    {
        expectError(lines({"GOCAD Model3d 1", "TSURF s", "TFACE 1 top s", "  0 0 0", "  1 0 0"}), 5,
                    "file ends inside the key triangle of TFACE 1");
    }

    void truncatedRegionList()
    {
        expectError(
            lines({"GOCAD Model3d 1", "TSURF s", "TFACE 1 top s", "REGION 2 Universe", "  -1 +1"}),
            5, "file ends inside the list of ids of REGION 'Universe'");
    }

    void truncatedHeaderBlock()
    {
        expectError(lines({"GOCAD TSurf 1", "HEADER {", "name: s"}), 3,
                    "file ends inside the HEADER block");
    }

    void regionListNotEndedByZero()
    {
        expectError(model3dHeader("  +1") + tsurf(), 12, "is not ended by 0");
    }

    void triangleWithUnknownVertex()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 0 0", "TRGL 1 2 9"), 7,
                    "TRGL refers to vertex 9");
    }

    void coordinateNotANumber()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 abc 0"), 5,
                    "y coordinate 'abc' is not a number");
    }

    void vertexIdNotAnInteger()
    {
        expectError(tsurf("VRTX 1.5 0 0 0"), 4, "vertex id '1.5' is not an integer");
    }

    void missingEndBeforeNextObject()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 0 0", "TRGL 1 2 3", "GOCAD TSurf 1") + tsurf(),
                    8, "missing END of TSurf 's'");
    }

    void missingEndAtEndOfFile()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 0 0", "TRGL 1 2 3", "BSTONE 1"), 8,
                    "file ends before the END of TSurf 's'");
    }

    void emptySurface()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 0 0", "TRGL 1 2 3", "TFACE")
                        + "VRTX 4 0 0 1\nEND\n",
                    8, "has no triangle (empty surface)");
    }

    void nanCoordinate()
    {
        expectError(tsurf("VRTX 1 0 0 nan"), 4, "z coordinate 'nan' is not finite");
    }

    void infiniteCoordinate()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 -inf 0"), 5,
                    "y coordinate '-inf' is not finite");
    }

    void nanInKeyTriangle()
    {
        std::string text = model3dHeader() + tsurf();
        text.replace(text.find("  1 0 0"), 7, "  1 NaN 0");
        expectError(text, 5, "is not finite");
    }

    void regionNamesUnknownTFace()
    {
        expectError(model3dHeader("  +7 0") + tsurf(), 11, "REGION 'R' names TFACE 7");
    }

    void atomRefersToUnknownVertex()
    {
        expectError(tsurf("VRTX 1 0 0 0", "ATOM 2 12"), 5, "ATOM 2 refers to vertex 12");
    }

    void duplicateVertexId()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 1 1 0 0"), 5,
                    "vertex id 1 is already defined at line 4");
    }

    void triangleRepeatsAVertex()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 0 0", "TRGL 1 2 1"), 7, "same vertex id twice");
    }

    void triangleWithTooFewIds()
    {
        expectError(tsurf("VRTX 1 0 0 0", "VRTX 2 1 0 0", "TRGL 1 2"), 7, "too few values");
    }

    void borderStoneOnUnknownVertex()
    {
        std::string text = tsurf();
        text.insert(text.find("END"), "BSTONE 42\n");
        expectError(text, 8, "BSTONE refers to vertex 42");
    }

    void invalidZPositive()
    {
        expectError(tsurf("ZPOSITIVE Up"), 4, "ZPOSITIVE must be Elevation or Depth");
    }

    void faceNamesUndeclaredTSurf()
    {
        std::string text = model3dHeader() + tsurf();
        text.replace(text.find("TFACE 1 top s"), 13, "TFACE 1 top t");
        expectError(text, 3, "names TSURF 't', which the header does not declare");
    }

    void declaredTSurfWithoutObject()
    {
        std::string text = model3dHeader() + tsurf();
        text.insert(text.find("TFACE 1"), "TSURF ghost\n"); // line 3
        expectError(text, 3, "TSURF 'ghost' has no TSurf object");
    }

    void undeclaredTSurfObject()
    {
        std::string body = tsurf();
        body.replace(body.find("name:s"), 6, "name:x");
        expectError(model3dHeader() + tsurf() + body, 21, "TSurf 'x' is not declared");
    }

    void faceCountMismatch()
    {
        std::string text = model3dHeader() + tsurf();
        text.insert(text.find("REGION 2"), "TFACE 9 top s\n"); // header: 2 TFACEs for s
        expectError(text, 14, "has 1 TFACEs but the Model3d header declares 2");
    }

    void notAGocadFile()
    {
        expectError("\nsolid ascii stl\nfacet normal 0 0 1\n", 2, "not a Gocad file");
    }

    void emptyFile() { expectError("# only a comment\n", 0, "empty file"); }

    void fileNotFound()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("missing_model.ml").toStdString();
        for (int reader = 0; reader < 2; ++reader) {
            try {
                reader == 0 ? readModel(path) : readGocadFile(path);
                QFAIL("no error raised");
            } catch (const FileError &e) {
                QCOMPARE(e.file(), path);
                QCOMPARE(e.line(), 0);
                QVERIFY2(std::string(e.what()).find("missing_model.ml: cannot open")
                             != std::string::npos,
                         e.what());
            }
        }
    }

    void unknownExtension()
    {
        try {
            readModel("/tmp/model.xyz");
            QFAIL("no error raised");
        } catch (const FileError &e) {
            QCOMPARE(e.file(), std::string("/tmp/model.xyz"));
            QVERIFY2(std::string(e.what()).find("unknown model file extension '.xyz'")
                         != std::string::npos,
                     e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestGocadErrors)
#include "test_gocad_errors.moc"
