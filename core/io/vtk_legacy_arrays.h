// The data arrays of a legacy .vtk file: values of any legacy type, big-endian in a BINARY file
// or whitespace-separated text in an ASCII one, each count checked against the bytes left in
// the file before anything is sized by it, and the METADATA block VTK may write after an array.
#pragma once

#include "io/vtk_legacy_cursor.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stratamesh {

enum class VtkLegacyType {
    Bit,
    Char,
    UnsignedChar,
    Short,
    UnsignedShort,
    Int,
    UnsignedInt,
    Long,
    UnsignedLong,
    Int64,
    UInt64,
    IdType, // 4 bytes in a file, as VTK writes it
    Float,
    Double,
    String
};

// The type a file names ("float", "vtktypeint64", "vtkIdType"... in any case), or none.
std::optional<VtkLegacyType> vtkLegacyType(std::string_view name);

// One array as StrataMesh keeps it: numbers as VTK's GetComponent gives them (doubles), or text.
struct VtkLegacyArray {
    std::string name;
    int components = 1;
    long long tuples = 0;
    bool text = false;          // a string array: `strings`, else `values`
    std::vector<double> values; // tuple after tuple
    std::vector<std::string> strings;
};

// Where the values of one array start: the cursor is past the end of its header's line.
struct VtkValuesAt {
    bool binary = false;
    std::string what; // names the array in messages: "POINTS", "SCALARS SurfaceId"...
    int headerLine = 0;
};

// `count` numbers of a numeric type. `lines`, when given, receives the line of each (ASCII).
std::vector<double> readVtkNumbers(VtkLegacyCursor &in, const VtkValuesAt &at, VtkLegacyType type,
                                   long long count, std::vector<int> *lines = nullptr);

// `count` signed integers of 4 or 8 bytes (cell lists, offsets, cell types), kept exact.
std::vector<long long> readVtkIntegers(VtkLegacyCursor &in, const VtkValuesAt &at, int bytes,
                                       long long count, std::vector<int> *lines = nullptr);

// `count` strings: one a line in ASCII (%XX escapes decoded), length-prefixed in BINARY.
std::vector<std::string> readVtkStrings(VtkLegacyCursor &in, const VtkValuesAt &at,
                                        long long count);

// The METADATA block VTK's reader looks for after each array (component names, information
// keys): skipped, as nothing StrataMesh reads depends on it.
void skipVtkMetadata(VtkLegacyCursor &in, int components);

// A name as VTK writes it, with "%XX" for bytes such as spaces, back to its bytes.
std::string vtkDecodedName(std::string_view name);

} // namespace stratamesh
