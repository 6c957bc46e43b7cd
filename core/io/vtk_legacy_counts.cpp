#include "io/vtk_legacy_counts.h"

#include "common/error.h"
#include "io/number_text.h"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace stratamesh {

namespace {

std::vector<std::string> words(const std::string &line)
{
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

bool isVtkTypeName(const std::string &w)
{
    static const std::set<std::string> names{
        "bit",           "unsigned_char", "char",   "unsigned_short", "short",  "unsigned_int",
        "int",           "unsigned_long", "long",   "float",          "double", "vtktypeint64",
        "vtktypeuint64", "vtkIdType",     "string", "utf8_string"};
    return names.count(w) > 0;
}

class Scanner {
public:
    Scanner(const std::string &path, long long size) : m_path(path), m_size(size) {}

    // One value per item at least (a byte in binary, a digit and a separator in ASCII): a
    // count beyond the file's size cannot be real.
    long long count(const std::vector<std::string> &w, std::size_t i, long long valuesPerItem,
                    int line) const
    {
        long long n = 0;
        if (i >= w.size() || !parseInt(w[i], n))
            throw FileError(m_path, line, w[0] + " needs a count");
        if (n < 0)
            throw FileError(m_path, line, w[0] + " declares a negative count " + std::to_string(n));
        if (n > m_size / valuesPerItem)
            throw FileError(m_path, line,
                            w[0] + " declares " + std::to_string(n)
                                + " items, more than the file of " + std::to_string(m_size)
                                + " bytes can hold");
        return n;
    }

private:
    std::string m_path;
    long long m_size;
};

// The 4.2 cell list "npts id id ... npts id ...": VTK 9.1 walks it without checking that each
// cell fits in the declared size, and crashes on a list that does not. Reads it (big-endian
// int32 in a BINARY file) and checks that its cells use exactly `size` values.
void checkCellList(std::istream &in, bool binary, long long cells, long long size,
                   const std::string &path, int &line, const std::string &keyword)
{
    const int start = line;
    std::vector<long long> values;
    values.reserve(static_cast<std::size_t>(size));
    if (binary) {
        std::string bytes(static_cast<std::size_t>(size) * 4, '\0');
        if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
            throw FileError(path, start, keyword + " data is cut short");
        for (long long i = 0; i < size; ++i) {
            const auto *b = reinterpret_cast<const unsigned char *>(bytes.data() + 4 * i);
            values.push_back(
                static_cast<std::int32_t>(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16
                                          | std::uint32_t(b[2]) << 8 | std::uint32_t(b[3])));
        }
    } else {
        std::string text;
        while (static_cast<long long>(values.size()) < size) {
            if (!std::getline(in, text))
                throw FileError(path, line,
                                keyword + " declares " + std::to_string(size)
                                    + " values, the file ends after "
                                    + std::to_string(values.size()));
            ++line;
            for (const std::string &w : words(text)) {
                long long v = 0;
                if (!parseInt(w, v))
                    throw FileError(path, line, keyword + " value '" + w + "' is not an integer");
                values.push_back(v);
            }
        }
    }
    long long at = 0;
    for (long long c = 0; c < cells; ++c) {
        const long long points = at < size ? values[static_cast<std::size_t>(at)] : -1;
        if (points < 0 || at + 1 + points > size)
            throw FileError(path, start,
                            keyword + " declares " + std::to_string(size) + " values, cell "
                                + std::to_string(c) + " (numbered from 0) runs past them");
        at += 1 + points;
    }
    if (at != size)
        throw FileError(path, start,
                        keyword + " declares " + std::to_string(size) + " values, its "
                            + std::to_string(cells) + " cells use " + std::to_string(at));
}

const char *const keywords[] = {"DATASET",      "POINTS",          "CELLS",
                                "CELL_TYPES",   "POLYGONS",        "LINES",
                                "VERTICES",     "TRIANGLE_STRIPS", "CELL_DATA",
                                "POINT_DATA",   "FIELD",           "SCALARS",
                                "VECTORS",      "NORMALS",         "TENSORS",
                                "LOOKUP_TABLE", "COLOR_SCALARS",   "TEXTURE_COORDINATES",
                                "METADATA",     "GLOBAL_IDS",      "PEDIGREE_IDS"};

// Binary bytes of a damaged header as '?', so that the message stays one line of text.
std::string printable(std::string text)
{
    for (char &c : text)
        if ((static_cast<unsigned char>(c) < 32 && c != '\t' && c != '\r')
            || static_cast<unsigned char>(c) > 126)
            c = '?';
    return text;
}

// Bytes per value of a legacy type in a BINARY file; 0 for a type whose size varies.
long long typeBytes(const std::string &type)
{
    if (type == "char" || type == "unsigned_char")
        return 1;
    if (type == "short" || type == "unsigned_short")
        return 2;
    if (type == "int" || type == "unsigned_int" || type == "float")
        return 4;
    if (type == "long" || type == "unsigned_long" || type == "double" || type == "vtkIdType"
        || type == "vtktypeint64" || type == "vtktypeuint64")
        return 8;
    return 0;
}

// The values of one version 5 array, after its "OFFSETS type" or "CONNECTIVITY type" line:
// big-endian in a BINARY file, whitespace-separated integers in an ASCII one.
std::vector<long long> readArray5(std::istream &in, bool binary, long long count, int bytes,
                                  const std::string &path, int &line, const std::string &what)
{
    std::vector<long long> values;
    values.reserve(static_cast<std::size_t>(count));
    if (binary) {
        std::string raw(static_cast<std::size_t>(count) * static_cast<std::size_t>(bytes), '\0');
        if (!in.read(raw.data(), static_cast<std::streamsize>(raw.size())))
            throw FileError(path, line, what + " data is cut short");
        for (long long i = 0; i < count; ++i) {
            std::uint64_t v = 0;
            for (int b = 0; b < bytes; ++b)
                v = v << 8
                    | static_cast<unsigned char>(raw[static_cast<std::size_t>(i * bytes + b)]);
            values.push_back(bytes == 4 ? static_cast<std::int32_t>(v) : static_cast<long long>(v));
        }
        return values;
    }
    std::string text;
    while (static_cast<long long>(values.size()) < count) {
        if (!std::getline(in, text))
            throw FileError(path, line,
                            what + " declares " + std::to_string(count)
                                + " values, the file ends after " + std::to_string(values.size()));
        ++line;
        for (const std::string &w : words(text)) {
            long long v = 0;
            if (!parseInt(w, v))
                throw FileError(path, line,
                                what + " value '" + printable(w.substr(0, 40))
                                    + "' is not an integer");
            if (static_cast<long long>(values.size()) == count)
                throw FileError(path, line,
                                what + " declares " + std::to_string(count)
                                    + " values, the line holds more");
            values.push_back(v);
        }
    }
    return values;
}

// The header line of a version 5 array: "OFFSETS vtktypeint64" (or vtktypeint32); its size.
int arrayHeader5(std::istream &in, const char *name, const std::string &path, int &line,
                 const std::string &keyword)
{
    std::string text;
    do {
        if (!std::getline(in, text))
            throw FileError(path, line,
                            "the file ends before the " + std::string(name) + " of " + keyword);
        ++line;
    } while (words(text).empty());
    const std::vector<std::string> w = words(text);
    if (w.size() != 2 || w[0] != name || (w[1] != "vtktypeint64" && w[1] != "vtktypeint32"))
        throw FileError(path, line,
                        keyword + " of a version 5 file goes on with \"" + name
                            + " vtktypeint64\" (or vtktypeint32), found \""
                            + printable(text.substr(0, 60)) + "\"");
    return w[1] == "vtktypeint64" ? 8 : 4;
}

// The version 5 cell section "offsets connectivity", then OFFSETS and CONNECTIVITY: VTK 9.1
// builds cells from offsets it never checks and reads on from a closed file after a bad array
// (fuzz_vtk_legacy findings: SEGVs in vtkDataReader::ReadString and vtkPolyData::GetCellType).
// Checks that the offsets start at 0, never decrease and end at the connectivity size.
void checkCellList5(std::istream &in, bool binary, long long offsets, long long connectivity,
                    const std::string &path, int &line, const std::string &keyword)
{
    const int start = line;
    if (offsets == 0) {
        if (connectivity != 0)
            throw FileError(path, start,
                            keyword + " declares no offsets but " + std::to_string(connectivity)
                                + " connectivity values");
        return;
    }
    const int offsetBytes = arrayHeader5(in, "OFFSETS", path, line, keyword);
    const std::vector<long long> offset =
        readArray5(in, binary, offsets, offsetBytes, path, line, keyword + " OFFSETS");
    const int connectivityBytes = arrayHeader5(in, "CONNECTIVITY", path, line, keyword);
    if (connectivityBytes != offsetBytes)
        throw FileError(path, line, keyword + " OFFSETS and CONNECTIVITY have different types");
    readArray5(in, binary, connectivity, connectivityBytes, path, line, keyword + " CONNECTIVITY");
    if (offset.front() != 0)
        throw FileError(path, start,
                        keyword + " OFFSETS start at " + std::to_string(offset.front())
                            + ", not 0");
    for (std::size_t c = 1; c < offset.size(); ++c)
        if (offset[c] < offset[c - 1])
            throw FileError(path, start,
                            keyword + " OFFSETS decrease at cell " + std::to_string(c - 1)
                                + " (numbered from 0)");
    if (offset.back() != connectivity)
        throw FileError(path, start,
                        keyword + " OFFSETS end at " + std::to_string(offset.back()) + ", "
                            + std::to_string(connectivity) + " connectivity values are declared");
}

// The arrays of a FIELD block, each "name components tuples type" then its values: VTK 9.1
// reads a malformed header as sizes and goes on into memory it does not own. Skips the values.
void checkFieldArrays(std::istream &in, bool binary, long long arrays, long long fileSize,
                      const std::string &path, int &line)
{
    std::string text;
    for (long long a = 0; a < arrays; ++a) {
        do {
            if (!std::getline(in, text))
                throw FileError(path, line,
                                "the file ends before FIELD array " + std::to_string(a + 1));
            ++line;
        } while (words(text).empty());
        const std::vector<std::string> w = words(text);
        long long components = 0, tuples = 0;
        if (w.size() != 4 || printable(text) != text || !parseInt(w[1], components)
            || !parseInt(w[2], tuples) || components < 0 || tuples < 0 || !isVtkTypeName(w[3]))
            throw FileError(path, line,
                            "FIELD array header \"" + printable(text.substr(0, 60))
                                + "\" is not \"name components tuples type\"");
        if (components > 0 && tuples > fileSize / components)
            throw FileError(path, line,
                            "array " + w[0] + " declares " + w[1] + " x " + w[2]
                                + " values, more than the file of " + std::to_string(fileSize)
                                + " bytes can hold");
        const long long values = components * tuples;
        if (binary) {
            const long long bytes = typeBytes(w[3]);
            if (bytes == 0)
                return; // strings and bits: VTK checks them itself
            in.ignore(static_cast<std::streamsize>(values * bytes));
            if (!in)
                throw FileError(path, line, "array " + w[0] + " is cut short");
            if (in.peek() == '\n')
                in.get();
        } else if (w[3] == "string" || w[3] == "utf8_string") {
            return;
        } else {
            long long read = 0;
            while (read < values) {
                if (!std::getline(in, text))
                    throw FileError(path, line, "array " + w[0] + " is cut short");
                ++line;
                read += static_cast<long long>(words(text).size());
            }
        }
    }
}

} // namespace

VtkLegacyCounts scanVtkLegacyCounts(const std::string &path)
{
    std::error_code ec;
    const auto size = static_cast<long long>(std::filesystem::file_size(path, ec));
    if (ec)
        throw FileError(path, 0, "cannot read the file size: " + ec.message());
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw FileError(path, 0, "cannot open the file");
    const Scanner scan(path, size);
    VtkLegacyCounts counts;
    bool version5 = false;
    bool binary = false;
    int unstructuredLine = 0; // line of DATASET UNSTRUCTURED_GRID, 0 for poly data
    bool sawPoints = false, inAttributes = false; // POINTS read; in POINT_DATA or CELL_DATA
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (line == 1) {
            version5 = text.find("Version 5") != std::string::npos;
            continue;
        }
        if (line == 3)
            binary = text.rfind("BINARY", 0) == 0;
        const std::vector<std::string> w = words(text);
        if (w.empty())
            continue;
        // VTK matches keywords by a case-blind prefix ("FIELD\xa0x" is FIELD to it): so do we,
        // and a keyword glued to other bytes is refused rather than read two ways.
        std::string key = w[0];
        for (char &c : key)
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        // An ASCII line of numbers never holds the word FIELD. VTK reads tokens, not lines: after
        // a number it cannot parse ("7FIELD7") it takes the rest for a FIELD keyword and
        // dereferences the null field data it fails to read (fuzz_vtk_legacy finding: a SEGV in
        // vtkPolyDataReader::ReadMeshSimple).
        if (!binary && !w[0].empty()
            && (std::isdigit(static_cast<unsigned char>(w[0][0])) || w[0][0] == '-'
                || w[0][0] == '+' || w[0][0] == '.')) {
            std::string upper = text;
            for (char &c : upper)
                c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            if (upper.find("FIELD") != std::string::npos)
                throw FileError(path, line, "a line of numbers holds the word FIELD");
        }
        for (const char *keyword : keywords)
            if (key.rfind(keyword, 0) == 0 && key != keyword)
                throw FileError(path, line,
                                "\"" + printable(w[0].substr(0, 40)) + "\" is not a VTK keyword");
        if (key == "DATASET") {
            if (w.size() < 2 || (w[1] != "UNSTRUCTURED_GRID" && w[1] != "POLYDATA"))
                throw FileError(
                    path, line,
                    "DATASET " + (w.size() < 2 ? std::string() : w[1])
                        + " is not read by StrataMesh (UNSTRUCTURED_GRID or POLYDATA only)");
            if (w[1] == "UNSTRUCTURED_GRID")
                unstructuredLine = line;
        } else if (key == "POINTS") {
            counts.points = {scan.count(w, 1, 3, line), line};
            sawPoints = true;
        } else if (key == "CELLS" || key == "POLYGONS" || key == "LINES" || key == "VERTICES"
                   || key == "TRIANGLE_STRIPS") {
            // Version 5 declares offsets (cells + 1) and connectivity; 4.2 cells and their ids.
            const int keyLine = line;
            long long n = scan.count(w, 1, 1, line);
            const long long values = scan.count(w, 2, 1, line);
            if (version5) {
                checkCellList5(in, binary, n, values, path, line, key);
                n = n > 0 ? n - 1 : 0;
            } else {
                checkCellList(in, binary, n, values, path, line, key);
            }
            counts.cells = {counts.cells.value < 0 ? n : counts.cells.value + n,
                            counts.cells.line ? counts.cells.line : keyLine};
        } else if (key == "FIELD") {
            // Field data belongs before POINTS or in an attribute section. VTK 9.1's dataset
            // readers take one between the geometry sections too, and dereference a null field
            // when it cannot be read (fuzz_vtk_legacy finding: a SEGV in ReadMeshSimple).
            if (sawPoints && !inAttributes)
                throw FileError(path, line,
                                "FIELD comes after POINTS outside POINT_DATA and CELL_DATA: "
                                "dataset field data goes before POINTS");
            // VTK reads the name and count with >>, whatever bytes they hold.
            if (w.size() != 3 || printable(text) != text)
                throw FileError(path, line,
                                "a FIELD line is \"FIELD name arrays\", found \""
                                    + printable(text.substr(0, 60)) + "\"");
            checkFieldArrays(in, binary, scan.count(w, 2, 1, line), size, path, line);
        } else if (key == "CELL_TYPES") {
            counts.cellTypes = {scan.count(w, 1, 1, line), line};
        } else if (key == "CELL_DATA") {
            // VTK 9.1's unstructured grid reader dereferences its cell arrays when cell data
            // comes before them (fuzz_vtk_legacy finding: a SEGV in ReadMeshSimple).
            if (unstructuredLine && (counts.cells.value < 0 || counts.cellTypes.value < 0))
                throw FileError(path, line,
                                "CELL_DATA comes before the CELLS and CELL_TYPES of the "
                                "unstructured grid");
            counts.cellData = {scan.count(w, 1, 1, line), line};
            inAttributes = true;
        } else if (key == "POINT_DATA") {
            counts.pointData = {scan.count(w, 1, 1, line), line};
            inAttributes = true;
        } else if (key == "LOOKUP_TABLE" && w.size() >= 3) {
            scan.count(w, 2, 4, line);
        } else if (key == "DIMENSIONS" || key == "X_COORDINATES" || key == "Y_COORDINATES"
                   || key == "Z_COORDINATES") {
            scan.count(w, 1, 1, line);
        } else if (w.size() == 4 && isVtkTypeName(w[3])) {
            // A FIELD array "name components tuples type": components x tuples values.
            long long components = 0, tuples = 0;
            if (parseInt(w[1], components) && parseInt(w[2], tuples)) {
                if (components < 0 || tuples < 0 || (components > 0 && tuples > size / components))
                    throw FileError(path, line,
                                    "array " + w[0] + " declares " + w[1] + " x " + w[2]
                                        + " values, more than the file of " + std::to_string(size)
                                        + " bytes can hold");
            }
        }
    }
    // Declared counts that disagree with each other: named with their line before VTK reads.
    auto agree = [&](const VtkLegacyCount &c, const VtkLegacyCount &with, const char *keyword,
                     const char *what) {
        if (c.value >= 0 && with.value >= 0 && c.value != with.value)
            throw FileError(path, c.line,
                            std::string(keyword) + " declares " + std::to_string(c.value)
                                + " values, " + what + " at line " + std::to_string(with.line)
                                + " declares " + std::to_string(with.value));
    };
    agree(counts.cellTypes, counts.cells, "CELL_TYPES", "CELLS");
    agree(counts.cellData, counts.cells, "CELL_DATA", "the cell section");
    agree(counts.pointData, counts.points, "POINT_DATA", "POINTS");
    return counts;
}

void checkVtkLegacyCounts(const std::string &path, const VtkLegacyCounts &declared,
                          long long points, long long cells)
{
    auto check = [&](const VtkLegacyCount &c, long long read, const char *keyword,
                     const char *what) {
        if (c.value >= 0 && c.value != read)
            throw FileError(path, c.line,
                            std::string(keyword) + " declares " + std::to_string(c.value) + " "
                                + what + ", " + std::to_string(read)
                                + " were read (short or misplaced section)");
    };
    check(declared.points, points, "POINTS", "points");
    check(declared.cells, cells, "the cell section", "cells");
    check(declared.cellTypes, cells, "CELL_TYPES", "cell types for the cells");
    check(declared.cellData, cells, "CELL_DATA", "values for the cells");
    check(declared.pointData, points, "POINT_DATA", "values for the points");
}

} // namespace stratamesh
