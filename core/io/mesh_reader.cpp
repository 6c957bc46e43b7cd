#include "io/mesh_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/formats.h"
#include "mesh/model_conversion.h"

namespace stratamesh {

bool isVolumeMeshFile(const std::string &path)
{
    const FileFormat *format = findFormat(path);
    return format != nullptr && format->holds == FormatHolds::VolumeMesh;
}

bool isMeshReaderFile(const std::string &path)
{
    return isFileFor(path, FormatUse::ReadVolumeMesh);
}

VolumeMesh readVolumeMesh(const std::string &path)
{
    const FileFormat *format = findFormat(path);
    if (format == nullptr || !format->readsMesh())
        throw FileError(
            path, 0,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "unknown mesh file extension '%1' (use %2)"),
                {fileExtension(path), extensionList(FormatUse::ReadVolumeMesh)}});
    return format->readMesh(path);
}

Model readMeshAsModel(const std::string &path)
{
    return modelFromMesh(readVolumeMesh(path));
}

} // namespace stratamesh
