// Hostile legacy VTK files (issue 18): a huge group id costs one group; a cell short of point ids,
// a cut or overlong section and any other syntax our legacy parser refuses are FileErrors naming
// the line, not a silently different mesh.
#include "bounded_read.h"
#include "common/error.h"
#include "io/model_reader.h"
#include "io/vtk_reader.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::testing;

namespace {

QByteArray triangleWithSurfaceId(const QByteArray &id)
{
    return "# vtk DataFile Version 4.2\nhostile\nASCII\nDATASET UNSTRUCTURED_GRID\n"
           "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\n"
           "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n"
           "CELL_DATA 1\nSCALARS SurfaceId int 1\nLOOKUP_TABLE default\n"
           + id + "\n";
}

} // namespace

class TestMalformedVtk : public QObject {
    Q_OBJECT

private slots:
    // Before: one name per id up to the largest, 23 s and 4.8 GB, then "out of memory".
    void hugeSurfaceIdIsOneSurface()
    {
        QTemporaryDir dir;
        const std::string path =
            writeTestFile(dir.path(), "huge_id.vtk", triangleWithSurfaceId("2147483647"));
        VolumeMesh mesh;
        const BoundedRead r = runBounded([&] {
            mesh = readVtk(path);
            if (mesh.surfaces.size() != 1 || mesh.surfaces[0].name != "surface_2147483648"
                || mesh.triangleSurface != std::vector<int>{0})
                throw std::runtime_error("wrong groups: " + std::to_string(mesh.surfaces.size())
                                         + " surfaces");
        });
        qInfo("huge SurfaceId: %s in %.3f s, +%ld KiB %s", outcomeName(r.outcome), r.seconds,
              r.peakKiB, r.message.c_str());
        QCOMPARE(outcomeName(r.outcome), outcomeName(BoundedRead::Read));
        QVERIFY2(r.peakKiB < 200 * 1024, r.message.c_str());
        QVERIFY(r.seconds < 2);
    }

    void sparseSurfaceIdsKeepTheirOrder()
    {
        QTemporaryDir dir;
        const QByteArray text =
            "# vtk DataFile Version 4.2\nsparse\nASCII\nDATASET UNSTRUCTURED_GRID\n"
            "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
            "CELLS 3 12\n3 0 1 2\n3 1 3 2\n3 0 1 3\nCELL_TYPES 3\n5\n5\n5\n"
            "CELL_DATA 3\nSCALARS SurfaceId int 1\nLOOKUP_TABLE default\n"
            "900000 1 900000\n";
        const VolumeMesh mesh = readVtk(writeTestFile(dir.path(), "sparse.vtk", text));
        // Sparse ids are numbered in increasing order; names keep the file's ids.
        QCOMPARE(int(mesh.surfaces.size()), 2);
        QCOMPARE(mesh.surfaces[0].name, std::string("surface_2"));
        QCOMPARE(mesh.surfaces[1].name, std::string("surface_900001"));
        QCOMPARE(mesh.triangleSurface, (std::vector<int>{1, 0, 1}));
    }

    void badSurfaceIdsAreFileErrors_data()
    {
        QTest::addColumn<QByteArray>("id");
        QTest::addColumn<QString>("cause");
        QTest::newRow("negative") << QByteArray("-1") << "SurfaceId -1";
        QTest::newRow("fraction") << QByteArray("2.5") << "SurfaceId 2.5";
        QTest::newRow("beyond int") << QByteArray("1e300") << "SurfaceId 1e+300";
    }
    void badSurfaceIdsAreFileErrors()
    {
        QFETCH(QByteArray, id);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        // A double array, so that the values are kept as written.
        QByteArray text = triangleWithSurfaceId(id);
        text.replace("SurfaceId int", "SurfaceId double");
        const std::string path = writeTestFile(dir.path(), "bad_id.vtk", text);
        try {
            readVtk(path);
            QFAIL("read a file with a bad SurfaceId");
        } catch (const FileError &e) {
            QVERIFY2(QString(e.what()).contains(cause), e.what());
            QCOMPARE(e.file(), path);
        }
    }

    // Before: the second cell took its missing third id from the first cell, exit 0.
    void cellShortOfPointIdsIsFileError()
    {
        QTemporaryDir dir;
        const QByteArray text =
            "# vtk DataFile Version 4.2\nshort\nASCII\nDATASET UNSTRUCTURED_GRID\n"
            "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
            "CELLS 2 7\n3 0 1 2\n2 1 3\nCELL_TYPES 2\n5\n5\n";
        const std::string path = writeTestFile(dir.path(), "short_cell.vtk", text);
        try {
            readModel(path);
            QFAIL("read a triangle with two point ids");
        } catch (const FileError &e) {
            QVERIFY2(QString(e.what()).contains(
                         "cell 1 (numbered from 0, VTK type 5) has 2 point ids, its "
                         "type needs 3"),
                     e.what());
        }
    }

    // Before: a cut CELLS section read as a mesh without cells, exit 0.
    void cutCellSectionIsFileError()
    {
        QTemporaryDir dir;
        const QByteArray text =
            "# vtk DataFile Version 4.2\ncut\nASCII\nDATASET UNSTRUCTURED_GRID\n"
            "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 1\n";
        const std::string path = writeTestFile(dir.path(), "cut.vtk", text);
        try {
            readModel(path);
            QFAIL("read a file cut inside CELLS");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), 10);
            QVERIFY2(QString(e.what()).contains("CELLS declares 4 values, the file ends after 3"),
                     e.what());
        }
    }

    // Before: VTK's reader printed its complaint about cut POINTS and went on; now our parser
    // names the line where the values stop.
    void cutPointsAreFileError()
    {
        QTemporaryDir dir;
        const QByteArray text =
            "# vtk DataFile Version 4.2\ncut\nASCII\nDATASET UNSTRUCTURED_GRID\n"
            "POINTS 3 double\n0 0 0\n1 0 0\n0 1\n";
        const std::string path = writeTestFile(dir.path(), "cut_points.vtk", text);
        try {
            readModel(path);
            QFAIL("read a file cut inside POINTS");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), 8);
            QCOMPARE(e.cause(), std::string("POINTS declares 9 values, the file ends after 8"));
        }
    }

    // Version 5 cell sections: VTK 9.1 builds cells from offsets it never checks (a SEGV in
    // vtkPolyData::GetCellType) and reads on from the file it closed after a bad array (a SEGV in
    // vtkDataReader::ReadString, fuzz_vtk_legacy finding in CI).
    void version5CellSectionsAreChecked_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        const QByteArray head = "# vtk DataFile Version 5.1\nv5\nASCII\nDATASET POLYDATA\n"
                                "POINTS 3 double\n0 0 0 1 0 0 0 1 0\n";
        const QByteArray off = "OFFSETS vtktypeint64\n";
        const QByteArray con = "CONNECTIVITY vtktypeint64\n";
        QTest::newRow("no offsets, connectivity")
            << head + "POLYGONS 0 4\n\x8d\xe0\x05\x00\xe0`\x00\x00" << 7
            << "POLYGONS declares no offsets but 4 connectivity values";
        QTest::newRow("offsets from 3") << head + "POLYGONS 2 3\n" + off + "3 0\n" + con + "0 1 2\n"
                                        << 7 << "POLYGONS OFFSETS start at 3, not 0";
        QTest::newRow("offsets decrease")
            << head + "POLYGONS 3 3\n" + off + "0 3 1\n" + con + "0 1 2\n"
            << 7 << "POLYGONS OFFSETS decrease at cell 1 (numbered from 0)";
        QTest::newRow("offsets past connectivity")
            << head + "POLYGONS 2 3\n" + off + "0 4\n" + con + "0 1 2\n"
            << 7 << "POLYGONS OFFSETS end at 4, 3 connectivity values are declared";
        QTest::newRow("no OFFSETS line")
            << head + "POLYGONS 2 3\n0 3\n" + con + "0 1 2\n"
            << 8 << "POLYGONS of a version 5 file goes on with \"OFFSETS";
        QTest::newRow("types differ")
            << head + "POLYGONS 2 3\n" + off + "0 3\nCONNECTIVITY vtktypeint32\n0 1 2\n"
            << 10 << "POLYGONS OFFSETS and CONNECTIVITY have different types";
        QTest::newRow("too many offsets")
            << head + "POLYGONS 2 3\n" + off + "0 3 3\n" + con + "0 1 2\n"
            << 9 << "POLYGONS OFFSETS declares 2 values, the line holds more";
        QTest::newRow("cut connectivity") << head + "POLYGONS 2 3\n" + off + "0 3\n" + con + "0 1\n"
                                          << 11 << "POLYGONS CONNECTIVITY declares 3 values";
        QTest::newRow("binary cut")
            << QByteArray("# vtk DataFile Version 5.1\nv5\nBINARY\nDATASET UNSTRUCTURED_GRID\n"
                          "CELLS 2 4\nOFFSETS vtktypeint64\n\0\0\0\0",
                          98)
            << 6 << "CELLS OFFSETS data is cut short";
    }
    void version5CellSectionsAreChecked()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), "v5.vtk", text);
        try {
            readModel(path);
            QFAIL("read a broken version 5 cell section");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), line);
            QVERIFY2(QString(e.what()).contains(cause), e.what());
        }
    }

    // What our parser of legacy files refuses, each with the line that causes it.
    void legacySyntaxErrorsNameTheirLine_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        const QByteArray head =
            "# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"; // lines 1-4
        const QByteArray points = "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\n";      // 5-8
        const QByteArray cells = "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n";        // 9-12
        const QByteArray data = "CELL_DATA 1\nSCALARS SurfaceId int 1\nLOOKUP_TABLE default\n";
        const QByteArray poly = "# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\n";
        QTest::newRow("newer version") << QByteArray("# vtk DataFile Version 5.2\nx\nASCII\n") << 1
                                       << "file version 5.2 is newer than the 5.1 StrataMesh reads";
        QTest::newRow("not ascii or binary")
            << QByteArray("# vtk DataFile Version 4.2\nx\nTEXT\n") << 3
            << "expected ASCII or BINARY after the title, found \"TEXT\"";
        QTest::newRow("points twice")
            << head + points + points << 9 << "a second POINTS (the first is at line 5)";
        QTest::newRow("no points") << poly + "POLYGONS 1 4\n3 0 1 2\n"
                                   << 0 << "the data set has no POINTS";
        QTest::newRow("points type")
            << head + "POINTS 3 real\n"
            << 5 << "POINTS has type 'real', which is not a legacy VTK data type";
        QTest::newRow("header junk") << head + "POINTS 3 double junk\n"
                                     << 5 << "the POINTS line is followed by 'junk' on its line";
        QTest::newRow("keyword among values")
            << head + "POINTS 3 double\n0 0 0\n1 0 0\nCELLS 1 4\n"
            << 8 << "POINTS declares 9 values, \"CELLS\" comes after 6";
        QTest::newRow("value beyond its line") << head + points + cells + data + "0 5\n"
                                               << 16
                                               << "SCALARS SurfaceId declares 1 values, the line "
                                                  "holds more";
        QTest::newRow("value beyond its count")
            << head + points + cells + data + "0\n5\n"
            << 17
            << "found \"5\" where a keyword belongs: the section before it holds more values "
               "than it declares";
        QTest::newRow("value out of range")
            << head + points + cells
                   + "CELL_DATA 1\nSCALARS SurfaceId short\nLOOKUP_TABLE t\n70000\n"
            << 16 << "SCALARS SurfaceId value '70000' is out of range for short";
        QTest::newRow("cells without types") << head + points + "CELLS 1 4\n3 0 1 2\n"
                                             << 9 << "CELLS has no CELL_TYPES to go with it";
        QTest::newRow("types disagree")
            << head + points + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 2\n5 5\n"
            << 11 << "CELL_TYPES declares 2 values, CELLS at line 9 declares 1";
        QTest::newRow("cell type not exchanged")
            << head + points + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n7\n"
            << 10 << "cell 0 has VTK type 7, which StrataMesh does not exchange";
        QTest::newRow("quad of poly data") << poly
                                                  + "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n"
                                                    "POLYGONS 2 9\n3 0 1 2\n4 0 1 2 3\n"
                                           << 9 << "cell 1 has VTK type 9";
        QTest::newRow("geometry after data") << head + points + cells + data + "0\nPOINTS 1 float\n"
                                             << 17
                                             << "POINTS comes after the data of the cells or "
                                                "points: the geometry goes first";
        QTest::newRow("unknown attribute") << head + points + cells + "CELL_DATA 1\nCOLOURS x\n"
                                           << 14 << "\"COLOURS\" is not a keyword of CELL_DATA";
        QTest::newRow("colour beyond 1")
            << head + points + cells + "CELL_DATA 1\nCOLOR_SCALARS c 1\n2\n"
            << 14 << "COLOR_SCALARS c holds 2, not a colour from 0 to 1";
        QTest::newRow("strings cut") << head + "FIELD f 1\nSurfaceNames 1 3 string\na\nb\n"
                                     << 8
                                     << "array SurfaceNames declares 3 strings, the file ends "
                                        "after 2";
        QTest::newRow("binary string cut")
            << QByteArray("# vtk DataFile Version 4.2\nx\nBINARY\nDATASET POLYDATA\n"
                          "FIELD f 1\nSurfaceNames 1 1 string\n\xc9"
                          "abc")
            << 6 << "array SurfaceNames data is cut short in string 1 of 1";
        QTest::newRow("offsets of another type")
            << QByteArray("# vtk DataFile Version 5.1\nx\nASCII\nDATASET POLYDATA\n") + points
                   + "POLYGONS 2 3\nOFFSETS int\n"
            << 10 << "POLYGONS OFFSETS has type 'int' (vtktypeint64 or vtktypeint32 expected)";
    }
    void legacySyntaxErrorsNameTheirLine()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), "syntax.vtk", text);
        try {
            readVtk(path);
            QFAIL("read a malformed legacy file");
        } catch (const FileError &e) {
            QCOMPARE(e.file(), path);
            QVERIFY2(QString::fromStdString(e.cause()).startsWith(cause), e.what());
            QCOMPARE(e.line(), line);
        }
    }

    // Before: each array's name was looked for among all the arrays before it (VTK's reader):
    // 100000 empty FIELD arrays, 1.6 MB, did not read in 120 s. Now a lookup each.
    void manyArraysReadInLinearTime()
    {
        QTemporaryDir dir;
        const int n = 50000;
        QByteArray text = "# vtk DataFile Version 4.2\nmany\nASCII\nDATASET POLYDATA\nFIELD f "
                          + QByteArray::number(n) + "\n";
        for (int i = 0; i < n; ++i)
            text += "a" + QByteArray::number(i) + " 1 0 int\n";
        text += "POINTS 3 double\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\nCELL_DATA 1\nFIELD g "
                + QByteArray::number(n) + "\n";
        for (int i = 0; i < n; ++i)
            text += "c" + QByteArray::number(i) + " 1 1 int\n0\n";
        const std::string path = writeTestFile(dir.path(), "many.vtk", text);
        const BoundedRead r = runBounded([&] { readVtk(path); });
        qInfo("%d + %d arrays: %s in %.3f s", n, n, outcomeName(r.outcome), r.seconds);
        QCOMPARE(outcomeName(r.outcome), outcomeName(BoundedRead::Read));
        QVERIFY(r.seconds < 5);
    }

    void hugeDeclaredCountsAreRefusedBeforeReading_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        const QByteArray head =
            "# vtk DataFile Version 4.2\nhuge\nASCII\nDATASET UNSTRUCTURED_GRID\n";
        QTest::newRow("points") << head + "POINTS 2000000000 double\n0 0 0\n" << 5;
        QTest::newRow("cells") << head + "POINTS 1 double\n0 0 0\nCELLS 3000000000 4\n" << 7;
        QTest::newRow("field array") << head + "FIELD FieldData 1\nSurfaceNames 1 2000000000 char\n"
                                     << 6;
        QTest::newRow("negative") << head + "POINTS -3 double\n" << 5;
        QTest::newRow("structured")
            << QByteArray("# vtk DataFile Version 4.2\nx\nASCII\nDATASET "
                          "STRUCTURED_POINTS\nDIMENSIONS 100000 100000 100000\n")
            << 4;
    }
    void hugeDeclaredCountsAreRefusedBeforeReading()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), "huge.vtk", text);
        const BoundedRead r = runBounded([&] { readModel(path); });
        QVERIFY2(r.outcome == BoundedRead::FileErrorRaised,
                 (outcomeName(r.outcome) + (": " + r.message)).c_str());
        QVERIFY2(QString::fromStdString(r.message).startsWith(QString::fromStdString(path) + ":"
                                                              + QString::number(line) + ": "),
                 r.message.c_str());
        QVERIFY(r.peakKiB < 200 * 1024);
    }
};

QTEST_GUILESS_MAIN(TestMalformedVtk)
#include "test_malformed_vtk.moc"
