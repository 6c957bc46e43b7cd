#include "io/ringmesh_entities.h"

#include "common/error.h"
#include "common/translate_noop.h"

#include <cstdlib>
#include <optional>
#include <sstream>

namespace stratamesh {

namespace {

std::vector<std::string> fields(const std::string &line)
{
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string f; in >> f;)
        out.push_back(std::move(f));
    return out;
}

class Lines {
public:
    Lines(const std::string &text, const std::string &where) : m_where(where)
    {
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) {
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            m_lines.push_back(fields(line));
        }
    }

    std::size_t size() const { return m_lines.size(); }
    int number() const { return int(m_next); } // 1-based number of the line last returned

    // The next non-empty line, or nullptr at the end.
    const std::vector<std::string> *next()
    {
        while (m_next < m_lines.size())
            if (!m_lines[m_next++].empty())
                return &m_lines[m_next - 1];
        return nullptr;
    }

    // The line right after an entity line (it may be empty: no boundaries).
    const std::vector<std::string> &following(const std::string &what)
    {
        if (m_next >= m_lines.size())
            fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "the file ends before the %1 line"), {what}});
        return m_lines[m_next++];
    }

    [[noreturn]] void fail(const std::string &cause) const
    {
        throw FileError(m_where, number(), cause);
    }
    [[noreturn]] void fail(const MessageText &cause) const
    {
        throw FileError(m_where, number(), cause);
    }

    long long integer(const std::string &s, const std::string &what) const
    {
        char *end = nullptr;
        const long long v = std::strtoll(s.c_str(), &end, 10);
        if (s.empty() || *end != '\0' || v < 0 || v > 2000000000)
            fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "expected %1 (a non-negative integer), found '%2'"),
                             {what, s}});
        return v;
    }

private:
    const std::string &m_where;
    std::vector<std::vector<std::string>> m_lines;
    std::size_t m_next = 0;
};

std::optional<GmEntityType> entityType(const std::string &s)
{
    for (int t = 0; t < kGmEntityTypes; ++t)
        if (s == gmEntityTypeName(GmEntityType(t)))
            return GmEntityType(t);
    return std::nullopt;
}

class MeshEntitiesParser {
public:
    MeshEntitiesParser(const std::string &text, const std::string &where)
        : m_in(text, where), m_where(where)
    {
    }

    GmMeshEntities run()
    {
        while (const std::vector<std::string> *f = m_in.next()) {
            const std::string &key = (*f)[0];
            if (key == "Version") {
                if (f->size() < 2)
                    m_in.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "'Version' without a number"));
                m_out.version = int(m_in.integer((*f)[1], "a version"));
                if (m_out.version > 2)
                    m_in.fail(MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "unknown .gm version %1 (versions 0, 1 and 2 are known)"),
                        {(*f)[1]}});
            } else if (key == "Dimension") {
                if (f->size() < 2 || (*f)[1] != "3")
                    m_in.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                                "only 3D GeoModels are supported (Dimension 3)"));
            } else if (key == "GeoModel") {
                if (f->size() > 2)
                    m_out.name = (*f)[2];
            } else if (key == "Nb") {
                count(*f);
            } else if (key == "Universe") {
                m_out.universe = signedIds(m_in.following("Universe sides"));
            } else if (const auto type = entityType(key)) {
                entity(*type, *f);
            } // other lines (from other RINGMesh versions) are ignored, as RINGMesh does
        }
        checkComplete();
        return std::move(m_out);
    }

private:
    void count(const std::vector<std::string> &f)
    {
        if (f.size() < 3)
            m_in.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "'Nb' line needs an entity type and a count"));
        const auto type = entityType(f[1]);
        if (!type)
            m_in.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "unknown mesh entity type '%1'"), {f[1]}});
        const long long n =
            m_in.integer(f[2], QT_TRANSLATE_NOOP("stratamesh::Core", "an entity count"));
        // Every entity takes two lines: a larger count cannot be honest.
        if (std::size_t(n) > m_in.size())
            m_in.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "Nb %1 %2 is more than the file's %3 lines can describe"),
                {f[1], f[2], std::to_string(m_in.size())}});
        auto &list = m_out.entities[int(*type)];
        if (!list.empty() || m_counted[int(*type)])
            m_in.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "second 'Nb %1' line"), {f[1]}});
        m_counted[int(*type)] = true;
        list.resize(std::size_t(n));
        m_defined[int(*type)].assign(std::size_t(n), false);
    }

    void entity(GmEntityType type, const std::vector<std::string> &f)
    {
        const std::string typeName = gmEntityTypeName(type);
        const std::size_t minFields = m_out.version == 1 ? 5 : 4;
        if (f.size() < minFields)
            m_in.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "%1 line has %2 fields, version %3 needs %4"),
                {typeName, std::to_string(f.size()), std::to_string(m_out.version),
                 std::to_string(minFields)}});
        const long long id =
            m_in.integer(f[1], QT_TRANSLATE_NOOP("stratamesh::Core", "an entity id"));
        auto &list = m_out.entities[int(type)];
        if (std::size_t(id) >= list.size())
            m_in.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 %2 is beyond 'Nb %1 %3'"),
                            {typeName, f[1], std::to_string(list.size())}});
        if (m_defined[int(type)][std::size_t(id)])
            m_in.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 %2 is defined twice"),
                                  {typeName, f[1]}});
        m_defined[int(type)][std::size_t(id)] = true;
        GmMeshEntity &e = list[std::size_t(id)];
        e.line = m_in.number();
        e.name = f[2];
        if (m_out.version == 2) {
            e.meshType = f[3];
        } else {
            e.feature = f[3];
            if (m_out.version == 1)
                e.meshType = f[4];
        }
        const std::vector<std::string> &second =
            m_in.following(typeName + " " + f[1] + " boundary");
        if (type == GmEntityType::Region) {
            e.sides = signedIds(second);
        } else {
            // RINGMesh skips the first field ("boundary") without looking at it.
            for (std::size_t i = 1; i < second.size(); ++i)
                e.boundaries.push_back(int(m_in.integer(
                    second[i], QT_TRANSLATE_NOOP("stratamesh::Core", "a boundary id"))));
        }
    }

    std::vector<GmSignedId> signedIds(const std::vector<std::string> &f)
    {
        std::vector<GmSignedId> out;
        for (const std::string &s : f) {
            if (s.size() < 2 || (s[0] != '+' && s[0] != '-'))
                m_in.fail(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "expected a signed surface id like +3 or -3, found '%1'"),
                    {s}});
            out.push_back({int(m_in.integer(s.substr(1), "a surface id")), s[0] == '+'});
        }
        return out;
    }

    void checkRange(int id, GmEntityType boundaryType, const GmMeshEntity &owner,
                    const std::string &ownerName)
    {
        const std::size_t n = m_out.entities[int(boundaryType)].size();
        if (id < 0 || std::size_t(id) >= n)
            throw FileError(
                m_where, owner.line,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "%1 has %2 %3 as boundary, but 'Nb %2' is %4"),
                            {ownerName, gmEntityTypeName(boundaryType), std::to_string(id),
                             std::to_string(n)}});
    }

    void checkComplete()
    {
        for (int t = 0; t < kGmEntityTypes; ++t) {
            const auto &defined = m_defined[t];
            for (std::size_t i = 0; i < defined.size(); ++i)
                if (!defined[i])
                    m_in.fail(
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "'Nb %1 %2' but %1 %3 is never described"),
                                    {gmEntityTypeName(GmEntityType(t)),
                                     std::to_string(defined.size()), std::to_string(i)}});
        }
        if (m_out.entities[int(GmEntityType::Surface)].empty())
            m_in.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "the GeoModel has no surface"));
        for (int t = 1; t < kGmEntityTypes; ++t) {
            const GmEntityType type = GmEntityType(t);
            const GmEntityType boundaryType = GmEntityType(t - 1);
            const auto &list = m_out.entities[t];
            for (std::size_t i = 0; i < list.size(); ++i) {
                const std::string owner =
                    std::string(gmEntityTypeName(type)) + " " + std::to_string(i);
                for (int b : list[i].boundaries)
                    checkRange(b, boundaryType, list[i], owner);
                for (const GmSignedId &s : list[i].sides)
                    checkRange(s.id, boundaryType, list[i], owner);
            }
        }
        for (const GmSignedId &s : m_out.universe)
            if (std::size_t(s.id) >= m_out.entities[int(GmEntityType::Surface)].size())
                m_in.fail(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "Universe has surface %1 as boundary, beyond 'Nb Surface'"),
                    {std::to_string(s.id)}});
    }

    Lines m_in;
    const std::string &m_where;
    GmMeshEntities m_out;
    std::array<bool, kGmEntityTypes> m_counted{};
    std::array<std::vector<bool>, kGmEntityTypes> m_defined;
};

} // namespace

const char *gmEntityTypeName(GmEntityType type)
{
    switch (type) {
    case GmEntityType::Corner:
        return "Corner";
    case GmEntityType::Line:
        return "Line";
    case GmEntityType::Surface:
        return "Surface";
    case GmEntityType::Region:
        return "Region";
    }
    return "?";
}

GmMeshEntities parseGmMeshEntities(const std::string &text, const std::string &where)
{
    return MeshEntitiesParser(text, where).run();
}

std::vector<GmGeologicalEntity> parseGmGeologicalEntities(const std::string &text,
                                                          const GmMeshEntities &mesh,
                                                          const std::string &where)
{
    Lines in(text, where);
    std::vector<GmGeologicalEntity> out;
    while (const std::vector<std::string> *f = in.next()) {
        const std::vector<std::string> &line = *f;
        if (line.size() >= 3 && line[0] == "No" && line[1] == "geological" && line[2] == "entity")
            break;
        if (line[0] == "Nb")
            continue; // the entities themselves say all we need
        if (line.size() < 4)
            in.fail(QT_TRANSLATE_NOOP(
                "stratamesh::Core",
                "geological entity line needs a type, an id, a name and a feature"));
        GmGeologicalEntity e;
        e.type = line[0];
        e.name = line[2];
        e.feature = line[3];
        e.line = in.number();
        in.integer(line[1], QT_TRANSLATE_NOOP("stratamesh::Core", "a geological entity id"));
        const std::vector<std::string> &children =
            in.following(e.type + " " + line[1] + " children");
        std::optional<GmEntityType> childType;
        if (e.type == "Interface")
            childType = GmEntityType::Surface;
        else if (e.type == "Contact")
            childType = GmEntityType::Line;
        else if (e.type == "Layer")
            childType = GmEntityType::Region;
        for (const std::string &c : children) {
            const long long id = in.integer(c, QT_TRANSLATE_NOOP("stratamesh::Core", "a child id"));
            if (childType && std::size_t(id) >= mesh.of(*childType).size())
                in.fail(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "%1 '%2' has %3 %4 as child, but mesh_entities.txt has %5"),
                    {e.type, e.name, gmEntityTypeName(*childType), c,
                     std::to_string(mesh.of(*childType).size())}});
            e.children.push_back(int(id));
        }
        out.push_back(std::move(e));
    }
    return out;
}

} // namespace stratamesh
