// The two text entries of a RINGMesh GeoModel archive (.gm), as RINGMesh's io_gm.cpp reads and
// writes them (checked on the RINGMeshData files).
//
// mesh_entities.txt: optional "Dimension 3", optional "Version N" (absent = 0), "GeoModel name X",
// "Nb Corner|Line|Surface|Region n", then two lines per entity:
//   version 0: "Surface 3 NAME FEATURE"            version 1: "Surface 3 NAME FEATURE
//   GeogramMesh2D" version 2: "Surface 3 NAME GeogramSurfaceMesh"
// followed by "boundary i j ..." (corners of a line, lines of a surface) or, for regions, the
// signed surfaces "+0 -9 ..." ("+": the region is on the side the surface normal points to).
// Last, "Universe" and its signed surfaces.
//
// geological_entities.txt: "Nb Interface|Contact|Layer n", then per entity "Interface 0 NAME
// FEATURE" and a line of children (surfaces of an interface, lines of a contact, regions of a
// layer); or the single line "No geological entity in the geomodel".
#pragma once

#include <array>
#include <string>
#include <vector>

namespace stratamesh {

enum class GmEntityType { Corner, Line, Surface, Region };
constexpr int kGmEntityTypes = 4;
const char *gmEntityTypeName(GmEntityType type); // "Corner", "Line", "Surface", "Region"

struct GmSignedId {
    int id = -1;
    bool positive = true;
};

struct GmMeshEntity {
    std::string name;              // "No_name" when RINGMesh had none
    std::string feature;           // versions 0 and 1 only
    std::string meshType;          // versions 1 and 2 only
    std::vector<int> boundaries;   // corners, lines, surfaces (unsigned)
    std::vector<GmSignedId> sides; // regions only
    int line = 0;                  // of its first line in mesh_entities.txt
};

struct GmMeshEntities {
    int version = 0;
    std::string name;
    std::array<std::vector<GmMeshEntity>, kGmEntityTypes> entities;
    std::vector<GmSignedId> universe;

    const std::vector<GmMeshEntity> &of(GmEntityType t) const { return entities[int(t)]; }
};

struct GmGeologicalEntity {
    std::string type; // "Interface", "Contact", "Layer"
    std::string name;
    std::string feature;
    std::vector<int> children;
    int line = 0;
};

// Throws FileError(where, line, cause) for a malformed line, an unknown version or entity type,
// an entity id beyond its "Nb" count or defined twice, a count with missing entities, or a
// boundary id out of range.
GmMeshEntities parseGmMeshEntities(const std::string &text, const std::string &where);

// Children are checked against the counts of `mesh` (interfaces → surfaces, contacts → lines,
// layers → regions); unknown entity types are kept unchecked.
std::vector<GmGeologicalEntity> parseGmGeologicalEntities(const std::string &text,
                                                          const GmMeshEntities &mesh,
                                                          const std::string &where);

} // namespace stratamesh
