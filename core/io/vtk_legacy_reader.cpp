#include "io/vtk_legacy_reader.h"

#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/number_text.h"
#include "io/vtk_common.h"

#include <vtkCellType.h>

#include <array>
#include <cstdio>
#include <unordered_map>

namespace stratamesh {

namespace {

// One cell list: CELLS, or VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS of poly data.
struct CellList {
    int line = 0; // of its keyword; 0 when the file has none
    std::vector<long long> offsets{0};
    std::vector<long long> connectivity;
    std::vector<int> cellLines; // where each cell is written (ASCII), else empty
};

// Which attributes a CELL_DATA or POINT_DATA section has set: VTK keeps the first of each kind
// and reads the others without keeping them.
struct Attributes {
    bool scalars = false, vectors = false, normals = false, tensors = false, tcoords = false,
         globalIds = false, pedigreeIds = false, edgeFlags = false;
};

constexpr std::array<const char *, 4> polyKeywords{"VERTICES", "LINES", "POLYGONS",
                                                   "TRIANGLE_STRIPS"};

// A later array of a name replaces the earlier one, as vtkFieldData::AddArray does; `index` finds
// it without a scan (a file of many arrays would cost their square).
void addArray(std::vector<VtkLegacyArray> &arrays,
              std::unordered_map<std::string, std::size_t> &index, VtkLegacyArray array)
{
    const auto [at, added] = index.emplace(array.name, arrays.size());
    if (added)
        arrays.push_back(std::move(array));
    else
        arrays[at->second] = std::move(array);
}

class Parser {
public:
    explicit Parser(const std::string &path) : m_in(path) {}

    VtkLegacyData run()
    {
        header();
        geometry();
        return std::move(m_data);
    }

private:
    [[noreturn]] void fail(int line, const std::string &cause) const { m_in.fail(line, cause); }
    [[noreturn]] void fail(int line, const MessageText &cause) const { m_in.fail(line, cause); }

    std::string upper(std::string_view token) const
    {
        std::string out(token);
        for (char &c : out)
            if (c >= 'a' && c <= 'z')
                c = static_cast<char>(c - 'a' + 'A');
        return out;
    }

    // The next token, which must be there: `what` says what it should be.
    std::string_view next(const std::string &what)
    {
        const int before = m_in.tokenLine();
        const std::string_view token = m_in.token();
        if (token.empty())
            fail(before,
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "the file ends before %1"),
                             {what}});
        return token;
    }

    long long count(const std::string &keyword)
    {
        const std::string_view token = next("the counts of " + keyword);
        long long n = 0;
        if (!parseInt(token, n))
            fail(m_in.tokenLine(), MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                                 "%1 needs a count, found \"%2\""),
                                               {keyword, vtkPrintable(token)}});
        if (n < 0)
            fail(m_in.tokenLine(), MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                                 "%1 declares a negative count %2"),
                                               {keyword, std::to_string(n)}});
        return n;
    }

    VtkLegacyType type(const std::string &what, bool text)
    {
        const std::string_view token = next("the type of " + what);
        const std::optional<VtkLegacyType> t = vtkLegacyType(token);
        if (!t)
            fail(m_in.tokenLine(),
                 MessageText{
                     QT_TRANSLATE_NOOP("stratamesh::Core",
                                       "%1 has type '%2', which is not a legacy VTK data type"),
                     {what, vtkPrintable(token)}});
        if (*t == VtkLegacyType::String && !text)
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "%1 has type '%2': it must hold numbers"),
                             {what, vtkPrintable(token)}});
        return *t;
    }

    void header()
    {
        std::string_view text;
        if (!m_in.line(text) || text.substr(0, 22) != "# vtk DataFile Version")
            fail(
                1,
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "not a legacy VTK file: the first line is not \"# vtk DataFile Version x.y\""));
        int major = 0, minor = 0;
        const std::string version(text.substr(22));
        if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) != 2)
            fail(1, MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core", "the file version '%1' is not x.y"),
                        {vtkPrintable(version.substr(
                            std::min(version.find_first_not_of(' '), version.size())))}});
        if (major > 5 || (major == 5 && minor > 1))
            fail(1, MessageText{QT_TRANSLATE_NOOP(
                                    "stratamesh::Core",
                                    "file version %1.%2 is newer than the 5.1 StrataMesh reads"),
                                {std::to_string(major), std::to_string(minor)}});
        m_version5 = major >= 5;
        if (!m_in.line(text))
            fail(1, QT_TRANSLATE_NOOP("stratamesh::Core", "the file ends before its title line"));
        const std::string_view mode = next("ASCII or BINARY");
        if (vtkKeywordIs(mode, "BINARY"))
            m_binary = true;
        else if (!vtkKeywordIs(mode, "ASCII"))
            fail(m_in.tokenLine(),
                 MessageText{
                     QT_TRANSLATE_NOOP("stratamesh::Core",
                                       "expected ASCII or BINARY after the title, found \"%1\""),
                     {vtkPrintable(mode)}});
        const std::string_view dataset = next("DATASET");
        if (!vtkKeywordIs(dataset, "DATASET"))
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "expected DATASET after %1, found \"%2\""),
                             {upper(mode), vtkPrintable(dataset)}});
        const std::string_view kind = next("the DATASET type");
        m_poly = vtkKeywordIs(kind, "POLYDATA");
        if (!m_poly && !vtkKeywordIs(kind, "UNSTRUCTURED_GRID"))
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "DATASET %1 is not read by StrataMesh "
                                               "(UNSTRUCTURED_GRID or POLYDATA only)"),
                             {vtkPrintable(kind)}});
    }

    // Refuses a section the file gives twice rather than keep one of them.
    void once(int &line, const std::string &keyword)
    {
        if (line)
            fail(m_in.tokenLine(),
                 MessageText{
                     QT_TRANSLATE_NOOP("stratamesh::Core", "a second %1 (the first is at line %2)"),
                     {keyword, std::to_string(line)}});
        line = m_in.tokenLine();
    }

    void geometry()
    {
        int fieldLine = 0;
        std::array<int, 4> polyLines{};
        for (std::string_view token; !(token = m_in.token()).empty();) {
            const std::string key = upper(token);
            if (key == "FIELD") {
                once(fieldLine, key);
                m_data.fieldArrays = field();
            } else if (key == "POINTS") {
                once(m_pointsLine, key);
                points();
            } else if (!m_poly && key == "CELLS") {
                once(m_grid.line, key);
                m_grid = cellList(key);
            } else if (!m_poly && key == "CELL_TYPES") {
                once(m_typesLine, key);
                cellTypes();
            } else if (key == "CELL_DATA" || key == "POINT_DATA") {
                finishGeometry();
                attributes(key);
                return;
            } else {
                std::size_t k = 0;
                while (k < polyKeywords.size() && key != polyKeywords[k])
                    ++k;
                if (!m_poly || k == polyKeywords.size())
                    unknown(token, "");
                once(polyLines[k], key);
                m_polyLists[k] = cellList(key);
            }
        }
        finishGeometry();
    }

    // A token where a keyword belongs: data beyond a declared count, or a word VTK does not know
    // here (in the geometry when `data` is empty, else in CELL_DATA or POINT_DATA).
    [[noreturn]] void unknown(std::string_view token, const std::string &data)
    {
        const char c = token[0];
        if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.')
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "found \"%1\" where a keyword belongs: the section "
                                               "before it holds more values than it declares"),
                             {vtkPrintable(token)}});
        const std::string known =
            !data.empty() ? std::string("SCALARS, COLOR_SCALARS, VECTORS, NORMALS, TENSORS, "
                                        "TEXTURE_COORDINATES, GLOBAL_IDS, PEDIGREE_IDS, ")
                                + (data == "POINT_DATA" ? "EDGE_FLAGS, " : "")
                                + "LOOKUP_TABLE, FIELD, CELL_DATA, POINT_DATA"
            : m_poly ? "FIELD, POINTS, VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, CELL_DATA, "
                       "POINT_DATA"
                     : "FIELD, POINTS, CELLS, CELL_TYPES, CELL_DATA, POINT_DATA";
        fail(
            m_in.tokenLine(),
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "\"%1\" is not a keyword of %2 (%3)"),
                        {vtkPrintable(token),
                         data.empty() ? m_poly ? "POLYDATA" : "UNSTRUCTURED_GRID" : data, known}});
    }

    void points()
    {
        const int line = m_in.tokenLine();
        const long long n = count("POINTS");
        const VtkLegacyType t = type("POINTS", false);
        if (t == VtkLegacyType::Bit)
            fail(m_in.tokenLine(),
                 QT_TRANSLATE_NOOP("stratamesh::Core",
                                   "POINTS has type 'bit': it must hold coordinates"));
        m_in.endLine("the POINTS line");
        if (static_cast<unsigned long long>(n) > m_in.remaining())
            fail(line,
                 MessageText{
                     QT_TRANSLATE_NOOP(
                         "stratamesh::Core",
                         "POINTS declares %1 points, more than the file of %2 bytes can hold"),
                     {std::to_string(n), std::to_string(m_in.fileSize())}});
        std::vector<int> lines;
        m_data.points =
            readVtkNumbers(m_in, {m_binary, "POINTS", line}, t, 3 * n, m_binary ? nullptr : &lines);
        skipVtkMetadata(m_in, 3);
        for (long long i = 0; i < n; ++i) {
            const double *p = &m_data.points[static_cast<std::size_t>(3 * i)];
            if (MessageText problem = pointProblem(p); !problem.pattern.empty())
                fail(lines.empty() ? line : lines[static_cast<std::size_t>(3 * i)],
                     MessageText{
                         QT_TRANSLATE_NOOP("stratamesh::Core", "point %1 (numbered from 0): %2"),
                         {std::to_string(i)},
                         {std::move(problem)}});
        }
    }

    // "OFFSETS vtktypeint64" or "CONNECTIVITY vtktypeint32" of a version 5 cell list: its bytes.
    int arrayHeader5(const char *name, const std::string &keyword)
    {
        const std::string_view token = next(std::string("the ") + name + " of " + keyword);
        if (!vtkKeywordIs(token, name))
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "%1 of a version 5 file goes on with \"%2 "
                                               "vtktypeint64\" (or vtktypeint32), found \"%3\""),
                             {keyword, name, vtkPrintable(token)}});
        const std::string_view t = next(std::string("the type of ") + keyword + " " + name);
        const int bytes = vtkKeywordIs(t, "VTKTYPEINT64")   ? 8
                          : vtkKeywordIs(t, "VTKTYPEINT32") ? 4
                                                            : 0;
        if (bytes == 0)
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP(
                                 "stratamesh::Core",
                                 "%1 %2 has type '%3' (vtktypeint64 or vtktypeint32 expected)"),
                             {keyword, name, vtkPrintable(t)}});
        m_in.endLine("the " + std::string(name) + " line");
        return bytes;
    }

    CellList cellList(const std::string &keyword)
    {
        CellList list;
        list.line = m_in.tokenLine();
        const long long first = count(keyword), second = count(keyword);
        m_in.endLine("the " + keyword + " line");
        return m_version5 ? cellList5(keyword, list, first, second)
                          : cellList4(keyword, list, first, second);
    }

    // Version 4.2 and before: `cells` cells in `size` values "npts id id ...", ids as 4-byte ints.
    CellList cellList4(const std::string &keyword, CellList list, long long cells, long long size)
    {
        if (cells > size)
            fail(list.line,
                 MessageText{QT_TRANSLATE_NOOP(
                                 "stratamesh::Core",
                                 "%1 declares %2 cells in %3 values: a cell takes one at least"),
                             {keyword, std::to_string(cells), std::to_string(size)}});
        std::vector<int> lines;
        const std::vector<long long> values = readVtkIntegers(m_in, {m_binary, keyword, list.line},
                                                              4, size, m_binary ? nullptr : &lines);
        long long at = 0;
        for (long long c = 0; c < cells; ++c) {
            const long long n = at < size ? values[static_cast<std::size_t>(at)] : -1;
            if (n < 0 || n > size - at - 1)
                fail(list.line,
                     MessageText{
                         QT_TRANSLATE_NOOP(
                             "stratamesh::Core",
                             "%1 declares %2 values, cell %3 (numbered from 0) runs past them"),
                         {keyword, std::to_string(size), std::to_string(c)}});
            if (!lines.empty())
                list.cellLines.push_back(lines[static_cast<std::size_t>(at)]);
            list.connectivity.insert(list.connectivity.end(), values.begin() + at + 1,
                                     values.begin() + at + 1 + n);
            list.offsets.push_back(static_cast<long long>(list.connectivity.size()));
            at += 1 + n;
        }
        if (at != size)
            fail(list.line,
                 MessageText{
                     QT_TRANSLATE_NOOP("stratamesh::Core",
                                       "%1 declares %2 values, its %3 cells use %4"),
                     {keyword, std::to_string(size), std::to_string(cells), std::to_string(at)}});
        return list;
    }

    // Version 5: `offsets` offsets (cells + 1, or none) then `connectivity` point ids.
    CellList cellList5(const std::string &keyword, CellList list, long long offsets,
                       long long connectivity)
    {
        if (offsets == 0) {
            if (connectivity != 0)
                fail(list.line,
                     MessageText{
                         QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "%1 declares no offsets but %2 connectivity values"),
                         {keyword, std::to_string(connectivity)}});
            return list;
        }
        const int offsetBytes = arrayHeader5("OFFSETS", keyword);
        std::vector<int> offsetLines, lines;
        list.offsets = readVtkIntegers(m_in, {m_binary, keyword + " OFFSETS", m_in.tokenLine()},
                                       offsetBytes, offsets, m_binary ? nullptr : &offsetLines);
        skipVtkMetadata(m_in, 1);
        if (arrayHeader5("CONNECTIVITY", keyword) != offsetBytes)
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "%1 OFFSETS and CONNECTIVITY have different types"),
                             {keyword}});
        list.connectivity =
            readVtkIntegers(m_in, {m_binary, keyword + " CONNECTIVITY", m_in.tokenLine()},
                            offsetBytes, connectivity, m_binary ? nullptr : &lines);
        skipVtkMetadata(m_in, 1);
        if (list.offsets.front() != 0)
            fail(list.line,
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 OFFSETS start at %2, not 0"),
                             {keyword, std::to_string(list.offsets.front())}});
        for (std::size_t c = 1; c < list.offsets.size(); ++c)
            if (list.offsets[c] < list.offsets[c - 1])
                fail(list.line, MessageText{QT_TRANSLATE_NOOP(
                                                "stratamesh::Core",
                                                "%1 OFFSETS decrease at cell %2 (numbered from 0)"),
                                            {keyword, std::to_string(c - 1)}});
        if (list.offsets.back() != connectivity)
            fail(list.line,
                 MessageText{
                     QT_TRANSLATE_NOOP("stratamesh::Core",
                                       "%1 OFFSETS end at %2, %3 connectivity values are declared"),
                     {keyword, std::to_string(list.offsets.back()), std::to_string(connectivity)}});
        // A cell is where its first point id is written, or its offset when it has none.
        if (!m_binary)
            for (std::size_t c = 0; c + 1 < list.offsets.size(); ++c) {
                const auto start = static_cast<std::size_t>(list.offsets[c]);
                list.cellLines.push_back(list.offsets[c + 1] > list.offsets[c] ? lines[start]
                                                                               : offsetLines[c]);
            }
        return list;
    }

    void cellTypes()
    {
        const long long n = count("CELL_TYPES");
        m_in.endLine("the CELL_TYPES line");
        const std::vector<long long> types =
            readVtkIntegers(m_in, {m_binary, "CELL_TYPES", m_typesLine}, 4, n);
        m_data.cellTypes.assign(types.begin(), types.end());
    }

    // Once the geometry is read: the cells in VTK's order, each checked against the points.
    void finishGeometry()
    {
        if (!m_pointsLine)
            fail(0, QT_TRANSLATE_NOOP("stratamesh::Core", "the data set has no POINTS"));
        std::vector<int> cellLines;
        if (!m_poly) {
            if (m_grid.line && !m_typesLine)
                fail(m_grid.line, QT_TRANSLATE_NOOP("stratamesh::Core",
                                                    "CELLS has no CELL_TYPES to go with it"));
            if (m_typesLine && !m_grid.line)
                fail(m_typesLine, QT_TRANSLATE_NOOP("stratamesh::Core",
                                                    "CELL_TYPES has no CELLS to go with it"));
            const long long cells = static_cast<long long>(m_grid.offsets.size()) - 1;
            if (static_cast<long long>(m_data.cellTypes.size()) != cells)
                fail(m_typesLine,
                     MessageText{QT_TRANSLATE_NOOP(
                                     "stratamesh::Core",
                                     "CELL_TYPES declares %1 values, CELLS at line %2 declares %3"),
                                 {std::to_string(m_data.cellTypes.size()),
                                  std::to_string(m_grid.line), std::to_string(cells)}});
            m_cellsLine = m_grid.line;
            m_data.offsets = std::move(m_grid.offsets);
            m_data.connectivity = std::move(m_grid.connectivity);
            cellLines = m_grid.cellLines.empty()
                            ? std::vector<int>(m_data.cellTypes.size(), m_grid.line)
                            : std::move(m_grid.cellLines);
        } else {
            for (std::size_t k = 0; k < m_polyLists.size(); ++k) {
                CellList &list = m_polyLists[k];
                if (!list.line)
                    continue;
                m_cellsLine = m_cellsLine ? std::min(m_cellsLine, list.line) : list.line;
                for (std::size_t c = 0; c + 1 < list.offsets.size(); ++c) {
                    const long long size = list.offsets[c + 1] - list.offsets[c];
                    m_data.cellTypes.push_back(polyType(k, size));
                    m_data.offsets.push_back(m_data.offsets.back() + size);
                    cellLines.push_back(list.cellLines.empty() ? list.line : list.cellLines[c]);
                }
                m_data.connectivity.insert(m_data.connectivity.end(), list.connectivity.begin(),
                                           list.connectivity.end());
                list = CellList();
            }
        }
        const auto points = static_cast<long long>(m_data.points.size() / 3);
        for (std::size_t c = 0; c < m_data.cellTypes.size(); ++c) {
            const long long begin = m_data.offsets[c], size = m_data.offsets[c + 1] - begin;
            const MessageText problem = vtkCellProblem(
                static_cast<long long>(c), m_data.cellTypes[c],
                size > 0 ? m_data.connectivity.data() + begin : nullptr, size, points);
            if (!problem.pattern.empty())
                fail(cellLines[c], problem);
        }
    }

    // The type vtkPolyData gives a cell of `size` points in list k (vertices, lines, polygons,
    // strips).
    static int polyType(std::size_t k, long long size)
    {
        switch (k) {
        case 0:
            return size == 1 ? VTK_VERTEX : VTK_POLY_VERTEX;
        case 1:
            return size == 2 ? VTK_LINE : VTK_POLY_LINE;
        case 2:
            return size == 3 ? VTK_TRIANGLE : size == 4 ? VTK_QUAD : VTK_POLYGON;
        default:
            return VTK_TRIANGLE_STRIP;
        }
    }

    // CELL_DATA n or POINT_DATA n, whose n must be the number of cells or of points.
    void section(const std::string &key)
    {
        const int line = m_in.tokenLine();
        const long long n = count(key);
        m_cellSection = key == "CELL_DATA";
        const long long have = m_cellSection ? static_cast<long long>(m_data.cellTypes.size())
                                             : static_cast<long long>(m_data.points.size() / 3);
        if (n != have) {
            if (m_cellSection && !m_cellsLine)
                fail(line, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                         "%1 declares %2 values, the cell section "
                                                         "is missing: the file has no cells"),
                                       {key, std::to_string(n)}});
            fail(line, MessageText{m_cellSection
                                       ? QT_TRANSLATE_NOOP("stratamesh::Core",
                                                           "%1 declares %2 values, the cell "
                                                           "section at line %3 declares %4")
                                       : QT_TRANSLATE_NOOP("stratamesh::Core",
                                                           "%1 declares %2 values, POINTS at line "
                                                           "%3 declares %4"),
                                   {key, std::to_string(n),
                                    std::to_string(m_cellSection ? m_cellsLine : m_pointsLine),
                                    std::to_string(have)}});
        }
        m_tuples = n;
    }

    void attributes(const std::string &first)
    {
        section(first);
        for (std::string_view token; !(token = m_in.token()).empty();) {
            const std::string key = upper(token);
            Attributes &set = m_cellSection ? m_cellAttributes : m_pointAttributes;
            if (key == "CELL_DATA" || key == "POINT_DATA")
                section(key);
            else if (key == "SCALARS")
                scalars(set);
            else if (key == "COLOR_SCALARS")
                colorScalars(set);
            else if (key == "VECTORS")
                keep(set.vectors, attribute(key, 3, false));
            else if (key == "NORMALS")
                keep(set.normals, attribute(key, 3, false));
            else if (key == "TENSORS")
                keep(set.tensors, attribute(key, 9, false));
            else if (key == "TENSORS6")
                keep(set.tensors, attribute(key, 6, false));
            else if (key == "TEXTURE_COORDINATES")
                keep(set.tcoords, attribute(key, 0, false));
            else if (key == "GLOBAL_IDS")
                keep(set.globalIds, attribute(key, 1, false));
            else if (key == "PEDIGREE_IDS")
                keep(set.pedigreeIds, attribute(key, 1, true));
            else if (key == "EDGE_FLAGS" && !m_cellSection)
                keep(set.edgeFlags, attribute(key, 1, false));
            else if (key == "LOOKUP_TABLE")
                lookupTable();
            else if (key == "FIELD")
                for (VtkLegacyArray &a : field())
                    keep(a);
            else if (key == "POINTS" || key == "CELLS" || key == "CELL_TYPES" || key == "VERTICES"
                     || key == "LINES" || key == "POLYGONS" || key == "TRIANGLE_STRIPS")
                fail(m_in.tokenLine(),
                     MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                   "%1 comes after the data of the cells or "
                                                   "points: the geometry goes first"),
                                 {key}});
            else
                unknown(token, m_cellSection ? "CELL_DATA" : "POINT_DATA");
        }
    }

    // Cell data StrataMesh may look up by name; point data is read for its syntax only.
    void keep(VtkLegacyArray &array)
    {
        if (m_cellSection)
            addArray(m_data.cellArrays, m_cellIndex, std::move(array));
    }
    void keep(bool &set, VtkLegacyArray array)
    {
        if (!set) {
            set = true;
            keep(array);
        }
    }

    // The values of an attribute of `components` per cell or point, after its header line.
    VtkLegacyArray values(VtkLegacyArray array, VtkLegacyType t, const std::string &what, int line)
    {
        m_in.endLine("the " + what + " line");
        if (array.components > 0
            && m_tuples > static_cast<long long>(m_in.fileSize()) / array.components)
            fail(line,
                 MessageText{
                     QT_TRANSLATE_NOOP("stratamesh::Core",
                                       "%1 declares %2 x %3 values, more than the file can hold"),
                     {what, std::to_string(m_tuples), std::to_string(array.components)}});
        array.tuples = m_tuples;
        const VtkValuesAt at{m_binary, what, line};
        if (t == VtkLegacyType::String) {
            array.text = true;
            array.strings = readVtkStrings(m_in, at, m_tuples * array.components);
        } else {
            array.values = readVtkNumbers(m_in, at, t, m_tuples * array.components);
        }
        skipVtkMetadata(m_in, array.components);
        return array;
    }

    // VECTORS name type, TEXTURE_COORDINATES name dim type, GLOBAL_IDS name type...
    VtkLegacyArray attribute(const std::string &key, int components, bool text)
    {
        const int line = m_in.tokenLine();
        VtkLegacyArray array;
        array.name = vtkDecodedName(next("the name of " + key));
        const std::string what = key + " " + array.name;
        array.components = components;
        if (components == 0) {
            long long dim = 0;
            const std::string_view token = next("the dimension of " + what);
            if (!parseInt(token, dim) || dim < 1 || dim > 3)
                fail(m_in.tokenLine(),
                     MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                   "%1 has dimension '%2' (1, 2 or 3 expected)"),
                                 {what, vtkPrintable(token)}});
            array.components = static_cast<int>(dim);
        }
        return values(std::move(array), type(what, text), what, line);
    }

    // SCALARS name type [components] then LOOKUP_TABLE table.
    void scalars(Attributes &set)
    {
        const int line = m_in.tokenLine();
        VtkLegacyArray array;
        array.name = vtkDecodedName(next("the name of SCALARS"));
        const std::string what = "SCALARS " + array.name;
        const VtkLegacyType t = type(what, false);
        std::string_view token = next("the LOOKUP_TABLE of " + what);
        if (!vtkKeywordIs(token, "LOOKUP_TABLE")) {
            long long components = 0;
            if (!parseInt(token, components) || components < 1 || components > 1 << 20)
                fail(m_in.tokenLine(),
                     MessageText{
                         QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "%1 has '%2' components (a number from 1 expected)"),
                         {what, vtkPrintable(token)}});
            array.components = static_cast<int>(components);
            token = next("the LOOKUP_TABLE of " + what);
            if (!vtkKeywordIs(token, "LOOKUP_TABLE"))
                fail(m_in.tokenLine(),
                     MessageText{QT_TRANSLATE_NOOP(
                                     "stratamesh::Core",
                                     "%1 goes on with \"LOOKUP_TABLE default\", found \"%2\""),
                                 {what, vtkPrintable(token)}});
        }
        next("the name of the LOOKUP_TABLE of " + what);
        keep(set.scalars, values(std::move(array), t, what, line));
    }

    // COLOR_SCALARS name components: bytes in BINARY, floats from 0 to 1 in ASCII.
    void colorScalars(Attributes &set)
    {
        const int line = m_in.tokenLine();
        VtkLegacyArray array;
        array.name = vtkDecodedName(next("the name of COLOR_SCALARS"));
        const std::string what = "COLOR_SCALARS " + array.name;
        long long components = 0;
        const std::string_view token = next("the components of " + what);
        if (!parseInt(token, components) || components < 1 || components > 1 << 20)
            fail(m_in.tokenLine(),
                 MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "%1 has '%2' components (a number from 1 expected)"),
                             {what, vtkPrintable(token)}});
        array.components = static_cast<int>(components);
        array = values(std::move(array),
                       m_binary ? VtkLegacyType::UnsignedChar : VtkLegacyType::Float, what, line);
        if (!m_binary)
            for (double &v : array.values) {
                const double byte = 255.0 * v + 0.5;
                if (!(byte >= 0 && byte < 256))
                    fail(line,
                         MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                       "%1 holds %2, not a colour from 0 to 1"),
                                     {what, doubleText(v)}});
                v = static_cast<unsigned char>(byte);
            }
        keep(set.scalars, std::move(array));
    }

    // LOOKUP_TABLE name size: size RGBA colours, read and not kept.
    void lookupTable()
    {
        const int line = m_in.tokenLine();
        const std::string what = "LOOKUP_TABLE " + vtkPrintable(next("the name of LOOKUP_TABLE"));
        const long long size = count(what);
        m_in.endLine("the " + what + " line");
        if (size > static_cast<long long>(m_in.fileSize()))
            fail(line,
                 MessageText{QT_TRANSLATE_NOOP(
                                 "stratamesh::Core",
                                 "%1 declares %2 colours, more than the file of %3 bytes can hold"),
                             {what, std::to_string(size), std::to_string(m_in.fileSize())}});
        readVtkNumbers(m_in, {m_binary, what, line},
                       m_binary ? VtkLegacyType::UnsignedChar : VtkLegacyType::Float, 4 * size);
    }

    // FIELD name arrays, then each array "name components tuples type" and its values.
    std::vector<VtkLegacyArray> field()
    {
        const int line = m_in.tokenLine();
        next("the name of FIELD");
        const long long n = count("FIELD");
        std::vector<VtkLegacyArray> arrays;
        std::unordered_map<std::string, std::size_t> index;
        for (long long a = 0; a < n; ++a) {
            const std::string_view name =
                next("FIELD array " + std::to_string(a + 1) + " of " + std::to_string(n)
                     + " (FIELD at line " + std::to_string(line) + ")");
            if (name == "NULL_ARRAY")
                continue;
            const int header = m_in.tokenLine();
            VtkLegacyArray array;
            array.name = vtkDecodedName(name);
            const std::string what = "array " + array.name;
            const long long components = count(what), tuples = count(what);
            if (components < 1 || components > 1 << 20)
                fail(header,
                     MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                   "%1 declares %2 components (from 1 to 1048576)"),
                                 {what, std::to_string(components)}});
            const VtkLegacyType t = type(what, true);
            m_in.endLine("the " + what + " line");
            if (tuples > static_cast<long long>(m_in.fileSize()) / components)
                fail(header,
                     MessageText{
                         QT_TRANSLATE_NOOP(
                             "stratamesh::Core",
                             "%1 declares %2 x %3 values, more than the file of %4 bytes can hold"),
                         {what, std::to_string(components), std::to_string(tuples),
                          std::to_string(m_in.fileSize())}});
            array.components = static_cast<int>(components);
            array.tuples = tuples;
            const VtkValuesAt at{m_binary, what, header};
            if (t == VtkLegacyType::String) {
                array.text = true;
                array.strings = readVtkStrings(m_in, at, components * tuples);
            } else {
                array.values = readVtkNumbers(m_in, at, t, components * tuples);
            }
            skipVtkMetadata(m_in, array.components);
            addArray(arrays, index, std::move(array));
        }
        return arrays;
    }

    VtkLegacyCursor m_in;
    bool m_binary = false, m_version5 = false, m_poly = false;
    int m_pointsLine = 0, m_typesLine = 0;
    int m_cellsLine = 0; // the first cell list, for messages about the number of cells
    CellList m_grid;
    std::array<CellList, 4> m_polyLists;
    bool m_cellSection = false; // in CELL_DATA rather than POINT_DATA
    long long m_tuples = 0;     // values per array of the current section
    Attributes m_cellAttributes, m_pointAttributes;
    std::unordered_map<std::string, std::size_t> m_cellIndex; // of m_data.cellArrays
    VtkLegacyData m_data;
};

} // namespace

VtkLegacyData readVtkLegacy(const std::string &path)
{
    return Parser(path).run();
}

} // namespace stratamesh
