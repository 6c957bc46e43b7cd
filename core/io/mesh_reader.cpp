#include "io/mesh_reader.h"

#include "common/error.h"
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
        throw FileError(path, 0,
                        "unknown mesh file extension '" + fileExtension(path) + "' (use "
                            + extensionList(FormatUse::ReadVolumeMesh) + ")");
    return format->readMesh(path);
}

Model readMeshAsModel(const std::string &path)
{
    return modelFromMesh(readVolumeMesh(path));
}

} // namespace stratamesh
