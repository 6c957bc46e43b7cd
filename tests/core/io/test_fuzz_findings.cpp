// Inputs the libFuzzer harnesses (tests/fuzz) found, kept as regression tests (issue 18): each
// must now end in a FileError, within 200 MB and a few seconds, in a forked child.
#include "bounded_read.h"
#include "common/error.h"
#include "io/mesh_reader.h"
#include "io/model_reader.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::testing;

namespace {

// fuzz_off: counts on a line of one word; the reader indexed past it (heap-buffer-overflow).
const char offCountsShort[] = "OFF\012"
                              "4 \012"
                              "4 2 0\012"
                              "2 0OF \012"
                              "0 2 \012"
                              "04\000\000\000";

// fuzz_vtk_legacy: a BINARY FIELD array header cut to "RegionNames 1 ", then binary values;
// VTK 9.1's legacy reader crashed (SEGV in vtkUnstructuredGridReader::ReadMeshSimple).
const char vtkFieldHeaderCut[] =
    "# vtk DataFile Version 4.2\012"
    "vtk output\012"
    "BINARY\012"
    "DATASET UNSTRUCTURED_GRID\012"
    "FIELD FieldData 7\012"
    "MeshName 1 7 unsigned_char\012"
    "square\012"
    "\012"
    "ZPositiveDepth 1 1 int\012"
    "\000\000\000\000\012"
    "RegionNames 1 \000\000\000\000\000\000\000\000\077\360\000\000\000\000\000\000\000"
    "\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\077\360\000\000\000\000"
    "\000\000\077\360\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000"
    "\000\000\000\000\000\077\360\000\000\000\000\000\000\077\340\000\000\000\000\000\000"
    "\012"
    "CELLS 6 20\012"
    "\000\000\000\003\000\000\000\000\000\000\000\001\000\000\000\002\000\000\000\003\000"
    "\000\000\000\000\000\000\002\000\000\000\003\000\000\000\002\000\000\000\000\000\000"
    "\000\001\000\000\000\002\000\000\000\001\000\000\000\002\000\000\000\002\000\000\000"
    "\002\000\000\000\003\000\000\000\002\000\000\000\003\000\000\000\000\012"
    "CELL_TYPES 6\012"
    "\000\000\000\005\000\000\000\005\000\000\000\003\000\000\000\003\000\000\000\003\000"
    "\000\000\003\012"
    "CELL_DATA 6\012"
    "FIELD FieldData 4\012"
    "RegionId 1 6 int\012"
    "\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\012"
    "SurfaceId 1 6 int\012"
    "\000\000\000\000\000\000\000\000\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\012"
    "LineId 1 6 int\012"
    "\377\377\377\377\377\377\377\377\000\000\000\000\000\000\000\000\000\000\000\000\000"
    "\000\000\000\012"
    "CellType 1 6 unsigned_char\012"
    "\005\005\003\003\003\003\012";

// fuzz_ply: no format line where OpenMesh looks for it; OpenMesh ran for over 10 s.
const char plyGarbledHeader[] =
    "ply\012"
    "fo\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377rmat ascii 1.0\012"
    "comment StrataMmat ascii 1.0\012"
    "comment Str\011\000\000er\012"
    "0 0 0\012"
    "1 0ader\012"
    "0 0 0\012"
    "1 0 0\012"
    "1 1 0\012"
    "0 1 0.2 3\012";

// fuzz_vtk_xml: a damaged compressed array; VTK 9.1 leaks the array it made for it (suppressed in
// tests/fuzz/lsan.supp), the read itself must still be a FileError.
const char vtuDamagedArray[] =
    "<\077xml version=\0421.0\042\077>\012"
    "<VTKFile type=\042UnstructuredGrid\042 version=\0421.0\042 byte_order=\042LittleE"
    "ndian\042 header_type=\042UInt64\042 compressor=\042vtkZLibDataCompressor\042>\012"
    "  <UnstructuredGrid>\012"
    "    <FieldData>\012"
    "      <DataArray type=\042UInt8\042 Name=\042MeshName\042 NumberOfTuples=\0427\042"
    " format=\042binary\042 RangeMin=\04210\042 RangeMax=\042117\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJwrLixNLErlAgALyQKc\012"
    "      </DataArray>\012"
    "      <DataArray type=\042Int32\042 Name=\042ZPositiveDepth\042 NumberOfTuples=\042"
    "1\042 format=\042binary\042 RangeMin=\0420\042 RangeMax=\0420\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAQAAAAAAAAADAAAAAAAAAA=eJxjYGBgAAAABAAB\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042RegionNames\042 NumberOfTuples=\0420"
    "\042 format=\042binary\042 RangeMin=\0421e+299\042 RangeMax=\042-1e+299\042>\012"
    "        AAAAAAAAAAAAgAAAAAAAAAAAAAAAAAAA\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042SurfaceNames\042 NumberOfTuples=\042"
    "7\042 format=\042binary\042 RangeMin=\04210\042 RangeMax=\042117\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJwrLixNLErlAgALyQKc\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042SurfaceFeatures\042 NumberOfTuples=\042"
    "7\042 format=\042binary\042 RangeMin=\04210\042 RangeMax=\042117\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJwrLixNLErlAgALyQKc\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042SurfaceTypes\042 NumberOfTuples=\042"
    "8\042 format=\042binary\042 RangeMin=\04210\042 RangeMax=\042119\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAgAAAAAAAAAEAAAAAAAAAA=eJwrzcvOyy/P4wIAD2EDGw==\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042LineNames\042 NumberOfTuples=\0427\042"
    " format=\042binary\042 RangeMin=\04210\042 RangeMax=\042110\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJzLycxLjTfgAgAKsgJC\012"
    "      </DataArray>\012"
    "    </FieldData>\012"
    "    <Piece NumberOfPoints=\0424\042 NumberOfCells=\0426\042>\012"
    "      <PointData>\012"
    "      </PointData>\012"
    "      <CellData>\012"
    "        <DataArray type=\042Int32\042 Name=\042RegionId\042 format=\042binary\042"
    " RangeMin=\042-1\042 RangeMax=\042-1\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAADAAAAAAAAAA=eJz7/x87AAAq+xfp\012"
    "        </DataArray>\012"
    "        <DataArray type=\042Int32\042 Name=\042SurfaceId\042 format=\042binary\042"
    " RangeMin=\042-1\042 RangeMax=\0420\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAADgAAAAAAAAA=eJxjYICA/2gAAIeQD/E=\012"
    "        </DataArray>\012"
    "        <DataArray type=\042Int32\042 Name=\042LineId\042 format=\042binary\042 R"
    "angeMin=\042-1\042 RangeMax=\0420\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAADgAAAAAAAAA=eJz7/x8CGNAAAKN0B/k=\012"
    "        </DataArray>\012"
    "        <DataArray type=\042UInt8\042 Name=\042CellType\042 format=\042binary\042"
    " RangeMin=\0423\042 RangeMax=\0425\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAAAYAAAAAAAAADAAAAAAAAAA=eJxjZWUGAgAAWwAX\012"
    "        </DataArray>\012"
    "      </CellData>\012"
    "      <Points>\012"
    "        <DataArray type=\042Float64\042 Name=\042Points\042 NumberOfComponents=\042"
    "3\042 format=\042binary\042 RangeMin=\0420\042 RangeMax=\0421.4142135623730951\042"
    ">\012"
    "          AQAAAAAAAAAAgAAAAAAAAGAAAAAAAAAAFAAAAAAAAAA=eJxjYMAHPtjjFyck/8AeALVLBdw"
    "=\012"
    "          <InformationKey name=\042L2_NORM_RANGE\042 location=\042vtkDataArray\042"
    " length=\0422\042>\012"
    "            <Value index=\0420\042>\012"
    "              0\012"
    "            </Value>\012"
    "            <Value index=\0421\042>\012"
    "              1.4142135624\012"
    "            </Value>\012"
    "          </InformationKey>\012"
    "        </DataArray>\012"
    "      </Points>\012"
    "      <Cells>\012"
    "        <DataArray type=\042Int64\042 Name=\042connectivity\042 format=\042binary"
    "\042 RangeMin=\0420\042 RangeMax=\0423\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAAHAAAAAAAAAAIAAAAAAAAAA=eJxjYIAARijNxIAKYHxmNHFGNJo"
    "JjWZGo2EAAASAABU=\012"
    "        </DataArray>\012"
    "        <DataArray type=\042Int64\042 Name=\042offsets\042 format=\042binary\042 "
    "RangeMin=\0423\042 RangeMax=\04214\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAADAAAAAAAAAAGAAAAAAAAAA=eJxjZoAANijNAaW5oDQPlOaD0gA"
    "E0AA2\012"
    "        </DataArray>\012"
    "        <DataArray type=\042UInt8\042 Name=\042types\042 format=\042binary\042 Ra"
    "ngeMin=\0423\042 RangeMax=\0425\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAAAYAAA:AAAAADAAAAAAAAAA=eJxjZWUGAgAAWwAX\012"
    "        </DataArray>\012"
    "      </Cells>\012"
    "    </Piece>\012"
    "  </UnstructuredGrid>\012"
    "</VTKFile>\012";

// fuzz_vtk_xml: a compressed array header stating a last block of 2.5e18 bytes; VTK 9.1 allocated
// it.
const char vtuHugeBlock[] =
    "<\077xml version=\0421.0\042\077>\012"
    "<VTKFile type=\042UnstructuredGrid\042 version=\0421.0\042 byte_order=\042LittleE"
    "ndian\042 header_type=\042UInt64\042 compressor=\042vtkZLibDataCompressor\042>\012"
    "  <UnstructuredGrid>\012"
    "    <FieldData>\012"
    "      <DataArray type=\042UInt8\042 Name=\042MeshName\042 NumberOfTuples=\0427\042"
    " format=\042binary\042 RangeMin=\04210\042 RangeMax=\042117\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJwrLixNLErlAgALyQKc\012"
    "      </DataArray>\012"
    "      <DataArray type=\042Int32\042 Name=\042ZPositiveDepth\042 NumberOfTuples=\042"
    "1\042 format=\042binary\042 RangeMin=\0420\042 RangeMax=\0420\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAQAAAAAAAAADAAAAAAAAAA=eJxjYGBgAAAABAAB\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042RegionNames\042 NumberOfTuples=\0420"
    "\042 format=\042binary\042 RangeMin=\0421e+299\042 RangeMax=\042-1e+299\042>\012"
    "        AAAAAAAAAAAAgAAAAAAAAAAAAAAAAAAA\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042SurfaceNames\042 NumberOfTuples=\042"
    "7\042 format=\042binary\042 RangeMin=\04210\042 RangeMax=\042117\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJwrLixNLErlAgALyQKc\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042SurfaceFeatures\042 NumberOfTuples=\042"
    "7\042 format=\042binary\042 RangeMin=\04210\042 RangeMax=\042117\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJwrLixNLErlAgALyQKc\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042SurfaceTypes\042 NumberOfTuples=\042"
    "8\042 format=\042binary\042 RangeMin=\04210\042 RangeMax=\042119\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAgAAAAAAAAAEAAAAAAAAAA=eJwrzcvOyy/P4wIAD2EDGw==\012"
    "      </DataArray>\012"
    "      <DataArray type=\042UInt8\042 Name=\042LineNames\042 NumberOfTuples=\0427\042"
    " format=\042binary\042 RangeMin=\04210\042 RangeMax=\042110\042>\012"
    "        AQAAAAAAAAAAgAAAAAAAAAcAAAAAAAAADwAAAAAAAAA=eJzLycxLjTfgAgAKsgJC\012"
    "      </DataArray>\012"
    "    </FieldData>\012"
    "    <Piece NumberOfPoints=\0424\042 NumberOfCells=\0426\042>\012"
    "      <PointData>\012"
    "      </PointData>\012"
    "      <CellData>\012"
    "        <DataArray type=\042Int32\042 Name=\042RegionId\042 format=\042binary\042"
    " RangeMin=\042-1\042 RangeMax=\042-1\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAADAAAAAAAAAA=eJz7/x87AAAq+xfp\012"
    "        </DataArray>\012"
    "        <DataArray type=\042Int32\042 Name=\042SurfaceId\042 format=\042binary\042"
    " RangeMin=\042-1\042 RangeMax=\0420\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAADgAAAAAAAAA=eJxjYICA/2gAAIeQD/E=\012"
    "        </DataArray>\012"
    "        <DataArray type=\042Int32\042 Name=\042LineId\042 format=\042binary\042 R"
    "angeMin=\042-1\042 RangeMax=\0420\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAADgAAAAAAAAA=eJz7/x8CGNAAAKN0B/k=\012"
    "        </DataArray>\012"
    "        <DataArray type=\042UInt8\042 Name=\042CellType\042 format=\042binary\042"
    " RangeMin=\0423\042 RangeMax=\0425\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAAAYAAAAAAAAADAAAAAAAAAA=eJxjZWUGAgAAWwAX\012"
    "        </DataArray>\012"
    "      </CellData>\012"
    "      <Points>\012"
    "        <DataArray type=\042Float64\042 Name=\042Points\042 NumberOfComponents=\042"
    "3\042 format=\042binary\042 RangeMin=\0420\042 RangeMax=\0421.4142135623730951\042"
    ">\012"
    "          AQAAAAAAAAAAgAAAAAAAAGAAAAAAAAAAFAAAAAAAAAA=eJxjYMAHPtjjFyck/8AeALVLBdw"
    "=\012"
    "          <InformationKey name=\042L2_NORM_RANGE\042 location=\042vtkDataArray\042"
    " length=\0422\042>\012"
    "            <Value index=\0420\042>\012"
    "              0\012"
    "            </Value>\012"
    "            <Value index=\0421\042>\012"
    "              1.4142135624\012"
    "            </Value>\012"
    "          </InformationKey>\012"
    "        </DataArray>\012"
    "      </Points>\012"
    "      <Cells>\012"
    "        <DataArray type=\042Int64\042 Name=\042connectivity\042 format=\042binary"
    "\042 RangeMin=\0420\042 RangeMax=\0423\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAAHAAAAAAAAAAIAAAAAAAAAA=eJxjYIAARijNxIAKYHxmNHFGNJo"
    "JjWZGo2EAAASAABU=\012"
    "        </DataArray>\012"
    "        <DataArray type=\042Int64\042 Name=\042offsets\042 format=\042binary\042 "
    "RangeMin=\0423\042 RangeMax=\04214\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAADAAAAAAAAAAGAAAAAAAAAA=eJxjZoAANijNAaW5oDQPlOaD0gA"
    "E0AA2\012"
    "        </DataArray>\012"
    "        <DataArray type=\042UInt8\042 Name=\042types\042 format=\042binary\042 Ra"
    "ngeMin=\0423\042 RangeMax=\0425\042>\012"
    "          AQAAAAAAAAAAgAAAAAAAAAYAARalgeMinAAAAAAAAAA=eJxjZWUGAgAAWwAX\012"
    "        </DataArray>\012"
    "      </Cells>\012"
    "    </Piece>\012"
    "  </UnstructuredGrid>\012"
    "</VTKFile>\012";

// fuzz_vtk_legacy: a FIELD line of five words with binary bytes in its name (VTK 9.1 SEGV).
const char vtkFieldLineGarbled[] =
    "# vtk DataFile Version 4.2\012"
    "vtk output\012"
    "BINARY\012"
    "DATASET UNSTRUCTURED_GRID\012"
    "FIELD \003\000\000\000\002\000\000\000\000\000\000\000\001\000\000es 1 0 unsigned"
    "_char\012"
    "\012"
    "SrfaceNames 1 7 unsigned_char\012"
    "square\012"
    "SurfaceId 1 6 int\012"
    "\000\000\000\000\000\000\000\000\377\377\377\377\377\377\377\377\377\377\377\377\377"
    "\377\377\377\377\012"
    "LineId 1 6 int\012"
    "\377\377\377\377\377\377\377\377\000\000\000\000\000\000\000\000\000\000\000\000\000"
    "\000\000\000\012"
    "CellType 1 6 unsigned_char\012"
    "\005\005\003\003\003\003\012";

// fuzz_vtk_legacy: "FIELD\240FieldData 7", which VTK takes for FIELD by its prefix (VTK 9.1 SEGV).
const char vtkFieldKeywordGlued[] =
    "# vtk DataFile Version 4.2\012"
    "vtk output\012"
    "BINARY\012"
    "DATASET UNSTRUCTURED_GRID\012"
    "FIELD\240FieldData 7\012"
    "MeshName 1 7 unsigned_char\012"
    "square\012"
    "\012"
    "ZPositiveDepth 1 1 ed_char\012"
    "\012"
    "SrfaceNames 1 7 unsigned_char\012"
    "\012"
    "SrfaceNames 1 7 unsigned_char\012"
    "square\012"
    "\012"
    "SurfaceFeatures 1 7 unsigned_char\012"
    "square\012"
    "\012"
    "SurfaceTypes 1 8 unsigned_char\012"
    "unknown\012"
    "\012"
    "LineNames 0 7 unsigned_char\012"
    "line_0\012"
    "\012"
    "POINTS 4 double\012"
    "\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000"
    "\000\000\000\077\360\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000"
    "\000\000\000\000\000\000\077_char\012"
    "unknown\012"
    "\012"
    "Lined_char\012"
    "\005\005\003\003\003\003\012";

QByteArray bytes(const char *data, std::size_t size)
{
    return QByteArray(data, int(size) - 1);
}

} // namespace

class TestFuzzFindings : public QObject {
    Q_OBJECT

private slots:
    void findingsAreFileErrors_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("data");
        QTest::newRow("off counts short")
            << "a.off" << bytes(offCountsShort, sizeof offCountsShort);
        QTest::newRow("vtk field header cut")
            << "a.vtk" << bytes(vtkFieldHeaderCut, sizeof vtkFieldHeaderCut);
        QTest::newRow("vtk field line garbled")
            << "b.vtk" << bytes(vtkFieldLineGarbled, sizeof vtkFieldLineGarbled);
        QTest::newRow("vtk field keyword glued")
            << "c.vtk" << bytes(vtkFieldKeywordGlued, sizeof vtkFieldKeywordGlued);
        QTest::newRow("ply garbled header")
            << "a.ply" << bytes(plyGarbledHeader, sizeof plyGarbledHeader);
        QTest::newRow("vtu damaged array")
            << "a.vtu" << bytes(vtuDamagedArray, sizeof vtuDamagedArray);
        QTest::newRow("vtu huge compressed block")
            << "b.vtu" << bytes(vtuHugeBlock, sizeof vtuHugeBlock);
    }
    void findingsAreFileErrors()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, data);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), name, data);
        const bool meshOnly = name.endsWith(".ply");
        const BoundedRead r =
            runBounded([&] { meshOnly ? void(readVolumeMesh(path)) : void(readModel(path)); });
        qInfo("%s: %s in %.3f s, +%ld KiB: %s", qPrintable(name), outcomeName(r.outcome), r.seconds,
              r.peakKiB, r.message.c_str());
        QVERIFY2(r.outcome == BoundedRead::FileErrorRaised,
                 (outcomeName(r.outcome) + (": " + r.message)).c_str());
        QVERIFY(QString::fromStdString(r.message).startsWith(QString::fromStdString(path) + ":"));
        QVERIFY(r.peakKiB < 200 * 1024);
        QVERIFY(r.seconds < 5);
    }
};

QTEST_GUILESS_MAIN(TestFuzzFindings)
#include "test_fuzz_findings.moc"
