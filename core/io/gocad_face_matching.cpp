#include "io/gocad_face_matching.h"

#include "common/error.h"
#include "common/translate_noop.h"

#include <cstring>
#include <functional>
#include <unordered_map>

namespace stratamesh {

namespace {

struct PointHash {
    std::size_t operator()(const Vec3 &p) const
    {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i) {
            const double c = p[i] + 0.0; // -0.0 and 0.0 compare equal: give them one hash
            std::uint64_t bits = 0;
            std::memcpy(&bits, &c, sizeof bits);
            h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        }
        return h;
    }
};

struct Candidate {
    int face = -1;
    bool reversed = false;
};

std::string faceLabel(const GocadHeaderFace &f)
{
    return "TFACE " + std::to_string(f.id) + " of TSURF '" + f.tsurf + "'";
}

// For every key, the body faces having a triangle with the key's vertex cycle, in one pass over
// the triangles (keys are indexed by their first point).
std::vector<std::vector<Candidate>>
findKeyCandidates(const std::vector<const GocadHeaderFace *> &headerFaces, const GocadTSurf &body)
{
    std::unordered_multimap<Vec3, int, PointHash> byFirstPoint;
    for (std::size_t k = 0; k < headerFaces.size(); ++k)
        if (headerFaces[k]->hasKey)
            byFirstPoint.emplace(headerFaces[k]->key[0], int(k));

    std::vector<std::vector<Candidate>> candidates(headerFaces.size());
    if (byFirstPoint.empty())
        return candidates;
    for (std::size_t f = 0; f < body.faces.size(); ++f) {
        const GocadFace &face = body.faces[f];
        for (const Triangle &t : face.triangles) {
            for (int r = 0; r < 3; ++r) {
                const Vec3 &p0 = face.vertices[t[r]];
                const auto range = byFirstPoint.equal_range(p0);
                for (auto it = range.first; it != range.second; ++it) {
                    const auto &key = headerFaces[it->second]->key;
                    const Vec3 &p1 = face.vertices[t[(r + 1) % 3]];
                    const Vec3 &p2 = face.vertices[t[(r + 2) % 3]];
                    bool reversed = false;
                    if (p1 == key[1] && p2 == key[2])
                        reversed = false;
                    else if (p2 == key[1] && p1 == key[2])
                        reversed = true;
                    else
                        continue;
                    auto &list = candidates[it->second];
                    if (list.empty() || list.back().face != int(f))
                        list.push_back({int(f), reversed});
                }
            }
        }
    }
    return candidates;
}

} // namespace

std::vector<GocadFaceMatch> matchGocadFaces(const std::vector<const GocadHeaderFace *> &headerFaces,
                                            const GocadTSurf &body, const std::string &fileName)
{
    const std::size_t n = headerFaces.size();
    if (body.faces.size() != n)
        throw FileError(
            fileName, body.info.firstLine,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "%1 has %2 TFACEs but the Model3d header declares %3 for it"),
                {describeGocadObject(body.info), std::to_string(body.faces.size()),
                 std::to_string(n)}});

    const auto candidates = findKeyCandidates(headerFaces, body);
    std::vector<GocadFaceMatch> matches(n);
    std::vector<char> taken(n, 0);
    auto assign = [&](std::size_t h, const Candidate &c) {
        matches[h] = {c.face, true, c.reversed};
        taken[c.face] = 1;
    };

    // 1. The key is in the face at the same position (every real sample).
    for (std::size_t h = 0; h < n; ++h)
        for (const Candidate &c : candidates[h])
            if (c.face == int(h) && !taken[h])
                assign(h, c);
    // 2. Reordered faces: the key is in exactly one face not yet matched.
    for (std::size_t h = 0; h < n; ++h) {
        if (matches[h].bodyFace >= 0 || candidates[h].empty())
            continue;
        std::vector<Candidate> free;
        for (const Candidate &c : candidates[h])
            if (!taken[c.face])
                free.push_back(c);
        if (free.size() > 1)
            throw FileError(
                fileName, headerFaces[h]->line,
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "the key triangle of %1 is a triangle of several TFACEs of %2"),
                            {faceLabel(*headerFaces[h]), describeGocadObject(body.info)}});
        if (free.size() == 1)
            assign(h, free.front());
    }
    // 3. No key, or a key found nowhere: by position.
    for (std::size_t h = 0; h < n; ++h) {
        if (matches[h].bodyFace >= 0)
            continue;
        if (taken[h])
            throw FileError(
                fileName, headerFaces[h]->line,
                MessageText{
                    QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "cannot match %1 to a TFACE of %2: its key triangle is in no remaining "
                        "TFACE and the TFACE at its position matches another one"),
                    {faceLabel(*headerFaces[h]), describeGocadObject(body.info)}});
        matches[h] = {int(h), false, false};
        taken[h] = 1;
    }
    return matches;
}

} // namespace stratamesh
