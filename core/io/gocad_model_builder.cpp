#include "io/gocad_model_builder.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/gocad_face_matching.h"
#include "io/surface_names.h"

#include <cstdlib>
#include <unordered_map>

namespace stratamesh {

namespace {

class Model3dBuilder {
public:
    Model3dBuilder(const GocadModel3dHeader &header, std::vector<GocadTSurf> bodies,
                   const std::string &fileName)
        : m_h(header), m_bodies(std::move(bodies)), m_file(fileName)
    {
    }

    Model run()
    {
        m_model.name = m_h.info.name.empty() ? gocadFileStem(m_file) : m_h.info.name;
        m_model.zPositiveDepth = m_h.info.zPositiveDepth;
        indexDeclarations();
        assignBodies();
        buildSurfaces();
        buildRegions();
        buildLayers();
        return std::move(m_model);
    }

private:
    [[noreturn]] void fail(int line, const std::string &cause) const
    {
        throw FileError(m_file, line, cause);
    }
    [[noreturn]] void fail(int line, const MessageText &cause) const
    {
        throw FileError(m_file, line, cause);
    }

    void indexDeclarations()
    {
        for (std::size_t t = 0; t < m_h.tsurfs.size(); ++t) {
            const auto [it, inserted] = m_tsurfIndex.emplace(m_h.tsurfs[t].name, int(t));
            if (!inserted)
                fail(m_h.tsurfs[t].line,
                     MessageText{
                         QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "TSURF '%1' is declared twice (first at line %2)"),
                         {m_h.tsurfs[t].name, std::to_string(m_h.tsurfs[it->second].line)}});
        }
        m_facesOfTsurf.resize(m_h.tsurfs.size());
        for (std::size_t f = 0; f < m_h.faces.size(); ++f) {
            const GocadHeaderFace &face = m_h.faces[f];
            const auto [it, inserted] = m_faceIndex.emplace(face.id, int(f));
            if (!inserted)
                fail(face.line,
                     MessageText{
                         QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "TFACE %1 is declared twice (first at line %2)"),
                         {std::to_string(face.id), std::to_string(m_h.faces[it->second].line)}});
            const auto t = m_tsurfIndex.find(face.tsurf);
            if (t == m_tsurfIndex.end())
                fail(
                    face.line,
                    MessageText{QT_TRANSLATE_NOOP(
                                    "stratamesh::Core",
                                    "TFACE %1 names TSURF '%2', which the header does not declare"),
                                {std::to_string(face.id), face.tsurf}});
            m_facesOfTsurf[t->second].push_back(int(f));
        }
    }

    // Body objects are found by name; an unnamed one takes the TSURF at its position.
    void assignBodies()
    {
        m_bodyOfTsurf.assign(m_h.tsurfs.size(), -1);
        for (std::size_t b = 0; b < m_bodies.size(); ++b) {
            const GocadObjectInfo &info = m_bodies[b].info;
            int t = int(b);
            if (!info.name.empty()) {
                const auto it = m_tsurfIndex.find(info.name);
                if (it == m_tsurfIndex.end())
                    fail(
                        info.firstLine,
                        MessageText{
                            QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "TSurf '%1' is not declared by a TSURF line of the Model3d header"),
                            {info.name}});
                t = it->second;
            } else if (t >= int(m_h.tsurfs.size())) {
                fail(info.firstLine,
                     QT_TRANSLATE_NOOP(
                         "stratamesh::Core",
                         "unnamed TSurf beyond the TSURFs declared by the Model3d header"));
            }
            if (m_bodyOfTsurf[t] >= 0)
                fail(info.firstLine,
                     MessageText{
                         QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "second TSurf object for TSURF '%1' (first at line %2)"),
                         {m_h.tsurfs[t].name,
                          std::to_string(m_bodies[m_bodyOfTsurf[t]].info.firstLine)}});
            m_bodyOfTsurf[t] = int(b);
        }
        for (std::size_t t = 0; t < m_h.tsurfs.size(); ++t)
            if (m_bodyOfTsurf[t] < 0)
                fail(
                    m_h.tsurfs[t].line,
                    MessageText{QT_TRANSLATE_NOOP(
                                    "stratamesh::Core",
                                    "TSURF '%1' has no TSurf object in the file (truncated file?)"),
                                {m_h.tsurfs[t].name}});
    }

    // SURFACE groups name the geological feature of faces; the first group naming a face wins.
    std::vector<std::string> groupNames() const
    {
        std::vector<std::string> names(m_h.faces.size());
        for (const GocadIdList &g : m_h.surfaceGroups)
            for (const GocadListedId &id : g.ids) {
                const auto it = m_faceIndex.find(std::llabs(id.id));
                if (it != m_faceIndex.end() && names[it->second].empty())
                    names[it->second] = g.name;
            }
        return names;
    }

    void buildSurfaces()
    {
        const std::vector<std::string> groups = groupNames();
        m_model.surfaces.resize(m_h.faces.size());
        m_reversed.assign(m_h.faces.size(), 0);
        for (std::size_t t = 0; t < m_h.tsurfs.size(); ++t) {
            const std::vector<int> &faceIds = m_facesOfTsurf[t];
            std::vector<const GocadHeaderFace *> headerFaces;
            for (int f : faceIds)
                headerFaces.push_back(&m_h.faces[f]);
            GocadTSurf &body = m_bodies[m_bodyOfTsurf[t]];
            const std::vector<GocadFaceMatch> matches = matchGocadFaces(headerFaces, body, m_file);
            const std::string &tsurfName = m_h.tsurfs[t].name;
            for (std::size_t k = 0; k < faceIds.size(); ++k) {
                const int f = faceIds[k];
                Surface &s = m_model.surfaces[f];
                s.name = patchName(tsurfName, faceIds.size(), k);
                s.featureName = !body.geologicalFeature.empty() ? body.geologicalFeature
                                : !groups[f].empty()            ? groups[f]
                                                                : tsurfName;
                s.type = featureTypeFromGocad(m_h.faces[f].type);
                if (s.type == FeatureType::Unknown && !body.geologicalType.empty())
                    s.type = featureTypeFromGocad(body.geologicalType);
                s.sourceObject = tsurfName;
                GocadFace &face = body.faces[matches[k].bodyFace];
                s.vertices = std::move(face.vertices);
                s.triangles = std::move(face.triangles);
                m_reversed[f] = matches[k].reversed;
            }
        }
        makeSurfaceNamesUnique(m_model);
    }

    std::vector<RegionSide> sides(const GocadIdList &region) const
    {
        std::vector<RegionSide> result;
        result.reserve(region.ids.size());
        for (const GocadListedId &id : region.ids) {
            const auto it = m_faceIndex.find(std::llabs(id.id));
            if (it == m_faceIndex.end())
                fail(id.line,
                     MessageText{
                         QT_TRANSLATE_NOOP(
                             "stratamesh::Core",
                             "REGION '%1' names TFACE %2, which the header does not declare"),
                         {region.name, std::to_string(std::llabs(id.id))}});
            // A key triangle written with the opposite cycle means the file's signs refer to
            // the other side of the triangles as stored.
            const bool positive = (id.id > 0) != bool(m_reversed[it->second]);
            result.push_back({it->second, positive});
        }
        return result;
    }

    void buildRegions()
    {
        for (std::size_t r = 0; r < m_h.regions.size(); ++r) {
            const GocadIdList &region = m_h.regions[r];
            const auto [it, inserted] = m_regionIndex.emplace(region.id, int(r) - 1);
            if (!inserted)
                fail(region.line, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                                "REGION id %1 is used twice"),
                                              {std::to_string(region.id)}});
            if (r == 0)
                m_model.universe = sides(region); // the first REGION is the outside
            else
                m_model.regions.push_back({region.name, sides(region)});
        }
    }

    // LAYER lists REGION ids; the Universe and unknown ids (seen in real files) are ignored.
    void buildLayers()
    {
        for (const GocadIdList &l : m_h.layers) {
            Layer layer;
            layer.name = l.name;
            for (const GocadListedId &id : l.ids) {
                const auto it = m_regionIndex.find(id.id);
                if (it != m_regionIndex.end() && it->second >= 0)
                    layer.regions.push_back(it->second);
            }
            m_model.layers.push_back(std::move(layer));
        }
    }

    const GocadModel3dHeader &m_h;
    std::vector<GocadTSurf> m_bodies;
    const std::string &m_file;
    Model m_model;
    std::unordered_map<std::string, int> m_tsurfIndex;
    std::unordered_map<long long, int> m_faceIndex;
    std::unordered_map<long long, int>
        m_regionIndex; // REGION id -> index in Model::regions, -1 Universe
    std::vector<std::vector<int>> m_facesOfTsurf;
    std::vector<int> m_bodyOfTsurf;
    std::vector<char> m_reversed;
};

} // namespace

std::string gocadFileStem(const std::string &fileName)
{
    const std::size_t slash = fileName.find_last_of("/\\");
    std::string base = slash == std::string::npos ? fileName : fileName.substr(slash + 1);
    const std::size_t dot = base.find_last_of('.');
    if (dot != std::string::npos && dot > 0)
        base.erase(dot);
    return base;
}

Model buildGocadModel3d(const GocadModel3dHeader &header, std::vector<GocadTSurf> bodies,
                        const std::string &fileName)
{
    return Model3dBuilder(header, std::move(bodies), fileName).run();
}

Model buildGocadSurfaces(std::vector<GocadTSurf> tsurfs, const std::string &fileName)
{
    if (tsurfs.empty())
        throw FileError(fileName, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "no TSurf object in the file"));
    Model model;
    model.name = gocadFileStem(fileName);
    model.zPositiveDepth = tsurfs.front().info.zPositiveDepth;
    for (std::size_t i = 0; i < tsurfs.size(); ++i) {
        GocadTSurf &ts = tsurfs[i];
        const std::string object = !ts.info.name.empty() ? ts.info.name
                                   : tsurfs.size() == 1  ? model.name
                                                         : model.name + "_" + std::to_string(i + 1);
        for (std::size_t k = 0; k < ts.faces.size(); ++k) {
            Surface s;
            s.name = patchName(object, ts.faces.size(), k);
            s.featureName = ts.geologicalFeature.empty() ? object : ts.geologicalFeature;
            s.type = ts.geologicalType.empty() ? FeatureType::Unknown
                                               : featureTypeFromGocad(ts.geologicalType);
            s.sourceObject = object;
            s.vertices = std::move(ts.faces[k].vertices);
            s.triangles = std::move(ts.faces[k].triangles);
            model.surfaces.push_back(std::move(s));
        }
    }
    makeSurfaceNamesUnique(model);
    return model;
}

} // namespace stratamesh
