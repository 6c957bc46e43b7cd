// A RINGMesh .gm archive opened for reading: its two text entries parsed and checked against
// each other and against the entry names, and the entity GeoFiles decoded on demand.
#pragma once

#include "io/geogram_file.h"
#include "io/ringmesh_entities.h"
#include "io/zip_archive.h"
#include "model/model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stratamesh {

// "Surface_3.geogram".
std::string gmEntryName(GmEntityType type, std::size_t i);

// A point by the bit patterns of its coordinates: exact matching, -0.0 apart from 0.0 as in
// the files.
struct PointKey {
    std::uint64_t x, y, z;
    bool operator==(const PointKey &o) const { return x == o.x && y == o.y && z == o.z; }
    bool operator<(const PointKey &o) const
    {
        return x != o.x ? x < o.x : y != o.y ? y < o.y : z < o.z;
    }
};
struct PointKeyHash {
    std::size_t operator()(const PointKey &k) const;
};
PointKey pointKey(const Vec3 &p);

class GmArchive {
public:
    // Throws FileError("archive:entry:line: cause") for a corrupt archive, a missing or malformed
    // mesh_entities.txt, a malformed geological_entities.txt, or a Type_i.geogram entry beyond
    // the counts of mesh_entities.txt.
    explicit GmArchive(const std::string &path);

    const std::string &path() const { return m_path; }
    std::string where(const std::string &entry) const { return m_path + ":" + entry; }
    const GmMeshEntities &entities() const { return m_entities; }
    const std::vector<GmGeologicalEntity> &geology() const { return m_geology; }
    bool has(GmEntityType type, std::size_t i) const;
    // Throws FileError naming the entry when it is missing or malformed.
    GeogramFile geogram(GmEntityType type, std::size_t i) const;

private:
    void checkEntries() const;

    std::string m_path;
    ZipReader m_zip;
    GmMeshEntities m_entities;
    std::vector<GmGeologicalEntity> m_geology;
};

} // namespace stratamesh
