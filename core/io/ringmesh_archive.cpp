#include "io/ringmesh_archive.h"

#include "common/error.h"
#include "common/translate_noop.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace stratamesh {

std::string gmEntryName(GmEntityType type, std::size_t i)
{
    return std::string(gmEntityTypeName(type)) + "_" + std::to_string(i) + ".geogram";
}

std::size_t PointKeyHash::operator()(const PointKey &k) const
{
    return std::hash<std::uint64_t>()(k.x * 0x9e3779b97f4a7c15ull ^ k.y * 0xc2b2ae3d27d4eb4full
                                      ^ k.z);
}

PointKey pointKey(const Vec3 &p)
{
    PointKey k;
    std::memcpy(&k.x, &p.x(), 8);
    std::memcpy(&k.y, &p.y(), 8);
    std::memcpy(&k.z, &p.z(), 8);
    return k;
}

GmArchive::GmArchive(const std::string &path) : m_path(path), m_zip(path)
{
    m_entities = parseGmMeshEntities(m_zip.read("mesh_entities.txt"), where("mesh_entities.txt"));
    // RINGMesh always writes it, but the meshes are usable without it.
    if (m_zip.contains("geological_entities.txt"))
        m_geology = parseGmGeologicalEntities(m_zip.read("geological_entities.txt"), m_entities,
                                              where("geological_entities.txt"));
    checkEntries();
}

bool GmArchive::has(GmEntityType type, std::size_t i) const
{
    return m_zip.contains(gmEntryName(type, i));
}

GeogramFile GmArchive::geogram(GmEntityType type, std::size_t i) const
{
    const std::string entry = gmEntryName(type, i);
    if (!m_zip.contains(entry))
        throw FileError(
            where(entry), 0,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "entry missing from the archive (mesh_entities.txt lists %1 %2)"),
                {std::string(gmEntityTypeName(type)), std::to_string(i)}});
    return readGeogramFile(m_zip.read(entry), where(entry));
}

// Every Type_i.geogram must name an entity of mesh_entities.txt.
void GmArchive::checkEntries() const
{
    for (const std::string &name : m_zip.names()) {
        const std::size_t underscore = name.find('_');
        const std::size_t dot = name.rfind(".geogram");
        if (underscore == std::string::npos || dot == std::string::npos || dot <= underscore + 1)
            continue;
        const std::string type = name.substr(0, underscore);
        const std::string digits = name.substr(underscore + 1, dot - underscore - 1);
        if (!std::all_of(digits.begin(), digits.end(),
                         [](unsigned char c) { return std::isdigit(c); }))
            continue;
        for (int t = 0; t < kGmEntityTypes; ++t) {
            const std::size_t count = m_entities.entities[t].size();
            if (type == gmEntityTypeName(GmEntityType(t))
                && (digits.size() > 9 || std::stoul(digits) >= count))
                throw FileError(
                    where(name), 0,
                    MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "no such entity: mesh_entities.txt says 'Nb %1 %2'"),
                        {type, std::to_string(count)}});
        }
    }
}

} // namespace stratamesh
