#include "io/mesh_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "mesh/model_conversion.h"

namespace stratamesh {

namespace {

const FileFormat &writableFormat(const std::string &path)
{
    const FileFormat *format = findFormat(path);
    if (format == nullptr || !format->writes())
        throw FileError(path, 0,
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "unknown output extension '%1' (use %2)"),
                                    {fileExtension(path), extensionList(FormatUse::Export)}});
    return *format;
}

} // namespace

bool isExportFile(const std::string &path)
{
    return isFileFor(path, FormatUse::Export);
}

ExportReport exportModel(const Model &model, const std::string &path, const ExportOptions &options)
{
    const FileFormat &format = writableFormat(path);
    ExportReport report;
    if (format.writeModel != nullptr)
        format.writeModel(model, path, options, report);
    else if (format.needsCells)
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "a TSolid holds tetrahedra: the surface model "
                                                  "'%1' has none (build a volume mesh first)"),
            {model.name}});
    else
        format.writeMesh(meshFromModel(model), path, options, report);
    return report;
}

ExportReport exportVolumeMesh(const VolumeMesh &mesh, const std::string &path,
                              const ExportOptions &options)
{
    const FileFormat &format = writableFormat(path);
    ExportReport report;
    // A format with both writers (RINGMesh) writes a mesh without cells as a B-Rep.
    if (format.writeMesh != nullptr && (mesh.hasCells() || format.writeModel == nullptr)) {
        format.writeMesh(mesh, path, options, report);
    } else {
        format.writeModel(modelFromMesh(mesh), path, options, report);
        report.cellsDropped = mesh.cells.size();
    }
    return report;
}

} // namespace stratamesh
