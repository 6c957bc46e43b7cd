// Every file format StrataMesh reads or writes, as one table: extension → readers, writers and
// what a model or a volume mesh keeps through the file. readModel() (model_reader.h),
// readVolumeMesh() (mesh_reader.h), exportModel() and exportVolumeMesh() (mesh_writer.h)
// dispatch through it, front ends ask it for their file-dialog filters and output checks, and
// tests/core/io/test_formats.cpp writes a model and a mesh built in code through every row and
// checks each capability claimed here, kept and dropped alike. A new format is one row.
#pragma once

#include "io/gmsh_writer.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <cstddef>
#include <string>
#include <vector>

namespace stratamesh {

struct ExportOptions {
    GmshWriteOptions gmsh;
    int surface = -1; // .ts and single-surface formats: one surface (index), or all / the only one
};

struct ExportReport {
    std::string format;              // "Gmsh MSH 4.1", "Gocad Model3d", ...
    std::size_t untaggedSkipped = 0; // Gmsh elements without a group left out (see saveAll)
    std::size_t cellsDropped = 0;    // volume cells a surface format cannot hold
};

// Which ExportOptions fields a format's writer reads, for an export dialog to offer them.
struct FormatOptions {
    bool gmsh = false;        // GmshWriteOptions: MSH version 4.1 or 2.2, saveAll
    bool surface = false;     // ExportOptions::surface: the writer takes one surface by index
    bool allSurfaces = false; // ... or every surface with surface = -1 (else only a lone one)
};

// What the file natively stands for.
enum class FormatHolds {
    Model,         // a B-Rep of surfaces and regions (Gocad Model3d and TSurf, RINGMesh)
    VolumeMesh,    // an exchange mesh that may hold cells (TSolid, Gmsh, VTK)
    SingleSurface, // one triangulated surface, no group (OBJ, OFF, STL, PLY)
};

// What survives writing a model (or a volume mesh) and reading it back.
struct FormatKeeps {
    bool severalSurfaces = false;  // a model with more than one surface can be written
    bool surfaceNames = false;     // surface names (TFACE, Gmsh physical names, VTK field data)
    bool featureTypes = false;     // horizon, fault, unconformity, boundary
    bool regions = false;          // regions with their names and boundary sides
    bool linesAndCorners = false;  // contact lines (named edges) and corners come back
    bool tetrahedra = false;       // volume cells: tetrahedra
    bool pyramidsPrisms = false;   // volume cells: pyramids and prisms (hybrid meshes)
    bool exactCoordinates = false; // doubles read back to the bit (STL stores 32-bit floats)
};

struct FileFormat {
    const char *extension; // lower case, with the dot: ".ml"
    const char *name;      // for file dialogs: "Gocad Model3d"
    FormatHolds holds;
    FormatKeeps keeps;
    // nullptr where the format has no such entry point. readModel returns no topology.
    Model (*readModel)(const std::string &path);
    VolumeMesh (*readMesh)(const std::string &path);
    // The writer of the format's own kind of data; the other kind is converted through
    // meshFromModel() / modelFromMesh() by exportModel() / exportVolumeMesh().
    void (*writeModel)(const Model &, const std::string &, const ExportOptions &, ExportReport &);
    void (*writeMesh)(const VolumeMesh &, const std::string &, const ExportOptions &,
                      ExportReport &);
    // True when writing a surface model is refused (a TSolid holds tetrahedra only).
    bool needsCells;
    FormatOptions options = {};

    bool readsModel() const { return readModel != nullptr; }
    bool readsMesh() const { return readMesh != nullptr; }
    bool writes() const { return writeModel != nullptr || writeMesh != nullptr; }
};

// The table, in the order file dialogs and error messages list it.
const std::vector<FileFormat> &fileFormats();

// The lower-case extension of the file name, with its dot (".ml"), or "" when there is none;
// as std::filesystem::path::extension(): "a/b.tar.GZ" → ".gz", "a/.ml" and "a.d/b" → "".
std::string fileExtension(const std::string &path);

// The file name without folders and its last extension, as std::filesystem::path::stem():
// "a/b.tar.gz" → "b.tar", "a/.ml" → ".ml"; what readers name an unnamed mesh or model after.
std::string fileStem(const std::string &path);

// The row of the path's extension (case-insensitive), or nullptr.
const FileFormat *findFormat(const std::string &path);

// What a front end asks for: a file to read a model from, a volume mesh from, a file to write
// a multi-surface model to (a remeshed model), a volume mesh with its cells to, or any file
// exportModel() / exportVolumeMesh() can write something to.
enum class FormatUse { ReadModel, ReadVolumeMesh, WriteModel, WriteVolumeMesh, Export };

bool formatServes(const FileFormat &format, FormatUse use);
// The rows serving `use`, in table order.
std::vector<const FileFormat *> formatsFor(FormatUse use);
// True when the path's extension serves `use`.
bool isFileFor(const std::string &path, FormatUse use);
// ".ml, .ts, .gm or .msh": the extensions serving `use`, for messages.
std::string extensionList(FormatUse use);

// A Qt file-dialog filter string: "ALL (*.ml *.ts …);;Gocad Model3d (*.ml);;…;;FILES (*)", with
// the labels of the first and last entries given by the caller (translated there); an empty
// label leaves that entry out.
std::string fileDialogFilter(FormatUse use, const std::string &allFormatsLabel,
                             const std::string &allFilesLabel);
// `path` itself when its extension serves `use`; otherwise path + the extension of the filter
// entry the user chose in the dialog (`selectedFilter`, one entry of fileDialogFilter), or of
// the first format serving `use`.
std::string withFormatExtension(const std::string &path, FormatUse use,
                                const std::string &selectedFilter);

// What an export writes: a surface model, or a volume mesh of tetrahedra only or with pyramids and
// prisms (a hybrid mesh). A volume mesh goes only to formats that keep its cells.
enum class ExportData { SurfaceModel, TetMesh, HybridMesh };

// Whether a format takes the data: NeedsCells for a surface model to a TSolid, DropsCells for a
// volume mesh to a format without cells, DropsPyramidsPrisms for a hybrid mesh to a TSolid.
enum class ExportFit { Fits, NeedsCells, DropsCells, DropsPyramidsPrisms };
ExportFit exportFit(const FileFormat &format, ExportData data);

// What the data loses through a format that fits it, from its FormatKeeps row, in the order of
// whatFormatDrops(); front ends put it in their own (translated) words.
enum class FormatLoss {
    OtherSurfaces, // all surfaces but one
    SurfaceNames,
    FeatureTypes,
    Regions,
    LinesAndCorners,
    VolumeCells,
    PyramidsPrisms,
    DoublePrecision, // coordinates as 32-bit floats
};
std::vector<FormatLoss> formatLosses(const FileFormat &format, ExportData data);
// In English, for the command line: "feature types".
std::string describe(FormatLoss loss);

// What writing to this format loses, in words ("feature types", "regions", ...), for an export
// dialog to warn with; empty when it keeps everything or the extension is unknown. `volume`
// asks about a volume mesh (its cells count), else about a surface model.
std::vector<std::string> whatFormatDrops(const std::string &path, bool volume);

} // namespace stratamesh
