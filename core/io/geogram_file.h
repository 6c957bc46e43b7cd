// Geogram's binary GeoFile (.geogram), the mesh file of every RINGMesh entity (formats.md, the
// .gm section). The file is gzip-compressed; inside, a sequence of chunks, each a 4-character
// class and a little-endian 64-bit byte size, then its body:
//   HEAD  string "GEOGRAM", string version ("1.0")       (must come first)
//   ATTS  string set name, uint32 item count             (an attribute set: vertices, facets...)
//   ATTR  string set, string name, string element type, uint32 element size, uint32 dimension,
//         then element size × dimension × items bytes    (an attribute of an earlier set)
//   CMNT  string; CMDL uint32 n, n strings; SPTR separates meshes (we read the first only)
// Strings are a uint32 length and that many bytes. Other classes are skipped by their size.
// Learnt from Geogram's geofile.cpp and mesh_io.cpp and checked on the RINGMeshData files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stratamesh {

struct GeogramAttribute {
    std::string set;
    std::string name;
    std::string elementType; // "double", "index_t", "char", ...
    std::uint32_t elementSize = 0;
    std::uint32_t dimension = 0;
    std::string data; // raw little-endian bytes, elementSize × dimension × items of the set
};

struct GeogramAttributeSet {
    std::string name;
    std::uint32_t items = 0;
};

struct GeogramFile {
    std::vector<GeogramAttributeSet> sets;
    std::vector<GeogramAttribute> attributes;
    std::vector<std::string> comments;
    std::vector<std::string> commandLine;

    const GeogramAttributeSet *findSet(const std::string &name) const;
    const GeogramAttribute *find(const std::string &set, const std::string &name) const;
};

// The decompressed bytes of a gzip stream. The output grows with what inflate really produces,
// so a lying size field cannot make it allocate. `where` names the data in errors
// ("model.gm:Surface_0.geogram"); throws FileError(where, cause).
std::string gunzip(const std::string &compressed, const std::string &where);
// gzip with the default compression level.
std::string gzip(const std::string &raw, const std::string &where);

// Parses decompressed GeoFile bytes. Every size field is checked against the bytes left before
// anything is allocated; throws FileError(where, "cause at byte N") on any inconsistency.
GeogramFile parseGeogramFile(const std::string &raw, const std::string &where);
// gunzip + parseGeogramFile.
GeogramFile readGeogramFile(const std::string &compressed, const std::string &where);

// The decompressed bytes of a GeoFile: HEAD, the comments, the command line, then every set
// followed by its attributes (as Geogram writes them). Attribute data sizes must match their
// set (InputError otherwise).
std::string serializeGeogramFile(const GeogramFile &file);
std::string writeGeogramFile(const GeogramFile &file, const std::string &where);

// Typed views on attribute data, for the element types RINGMesh writes.
std::vector<double> geogramDoubles(const GeogramAttribute &a, const std::string &where);
std::vector<std::uint32_t> geogramIndices(const GeogramAttribute &a, const std::string &where);
GeogramAttribute geogramAttribute(std::string set, std::string name,
                                  const std::vector<double> &values, std::uint32_t dimension);
GeogramAttribute geogramAttribute(std::string set, std::string name,
                                  const std::vector<std::uint32_t> &values,
                                  std::uint32_t dimension);

} // namespace stratamesh
