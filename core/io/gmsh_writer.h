// Gmsh MSH 4.1 and 2.2 ASCII output (formats.md §2): one entity and one named physical group per
// region (3D), surface (2D) and line (1D); corners are point entities in a physical group
// "corners". Node order is Gmsh's, which is ours (volume_mesh.h): cells are written unpermuted.
// Coordinates are written in the shortest form that reads back bit-exactly.
#pragma once

#include "mesh/volume_mesh.h"

#include <cstddef>
#include <string>

namespace stratamesh {

struct GmshWriteOptions {
    enum class Version { V41, V22 };
    Version version = Version::V41;
    // Gmsh itself keeps only elements of physical groups once any group exists (Mesh.SaveAll=0).
    // Untagged elements (group -1) are therefore skipped unless saveAll: then they go to an extra
    // entity with no physical group (physical tag 0 in MSH 2.2).
    bool saveAll = false;
};

struct GmshWriteResult {
    std::size_t elementsWritten = 0;
    std::size_t untaggedSkipped = 0; // elements left out because they have no group and !saveAll
};

// Writes atomically; throws InputError for an invalid mesh, FileError when the file cannot be
// written.
GmshWriteResult writeGmsh(const VolumeMesh &mesh, const std::string &path,
                          const GmshWriteOptions &options = {});

} // namespace stratamesh
