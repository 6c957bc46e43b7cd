#include "io/tsolid_reader.h"

#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/formats.h"
#include "io/number_text.h"
#include "io/text_cursor.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <unordered_map>

namespace stratamesh {

namespace {

// Whitespace-separated tokens; a double-quoted token may hold blanks (quotes removed).
std::vector<std::string> splitQuoted(std::string_view line)
{
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
            ++i;
        if (i >= line.size())
            break;
        std::string token;
        if (line[i] == '"') {
            const std::size_t close = line.find('"', i + 1);
            const std::size_t end = close == std::string_view::npos ? line.size() : close;
            token = std::string(line.substr(i + 1, end - i - 1));
            i = end + 1;
        } else {
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
                token += line[i++];
        }
        out.push_back(std::move(token));
    }
    return out;
}

std::string upper(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::toupper(c)); });
    return s;
}

std::string trim(std::string_view s)
{
    const std::size_t a = s.find_first_not_of(" \t");
    if (a == std::string_view::npos)
        return {};
    const std::size_t b = s.find_last_not_of(" \t");
    return std::string(s.substr(a, b - a + 1));
}

class TSolidParser {
public:
    explicit TSolidParser(const std::string &path) : c(path) {}

    VolumeMesh run()
    {
        bool started = false;
        while (c.next()) {
            const std::vector<std::string> t = splitQuoted(c.line());
            if (t.empty())
                continue;
            const std::string key = upper(t[0]);
            if (!started) {
                if (key != "GOCAD")
                    c.fail(QT_TRANSLATE_NOOP("stratamesh::Core",
                                             "not a Gocad file (expected \"GOCAD TSolid 1\")"));
                if (t.size() < 2 || (upper(t[1]) != "TSOLID" && upper(t[1]) != "LIGHTTSOLID"))
                    c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                         "expected a TSolid object, found \"%1\""),
                                       {trim(c.line())}});
                light = upper(t[1]) == "LIGHTTSOLID";
                started = true;
                continue;
            }
            if (key == "END")
                break;
            if (key == "HEADER" || key == "HEADER:")
                readHeader();
            else if (key == "ZPOSITIVE")
                mesh.zPositiveDepth = t.size() > 1 && upper(t[1]) == "DEPTH";
            else if (key == "TVOLUME")
                startVolume(t);
            else if (key == "VRTX" || key == "PVRTX")
                addVertex(t);
            else if (key == "ATOM" || key == "PATOM" || key == "SHAREDVRTX" || key == "SHAREDPVRTX")
                addAtom(t);
            else if (key == "TETRA")
                addTetra(t);
            else if (key == "#")
                readComment(t);
            else if (key == "MODEL")
                inModel = true;
            else if (key == "SURFACE" && inModel)
                feature = t.size() > 1 ? t[1] : "surface";
            else if (key == "TFACE" && inModel)
                startFace(t);
            else if (key == "TRGL")
                addTriangle(t);
            else if (key == "PROPERTY_CLASS_HEADER" && c.line().find('{') != std::string_view::npos)
                skipBlock();
            // Everything else (properties, KEYVERTICES, MODEL_REGION, CRS names...) is not needed.
        }
        if (!started)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "empty file: not a Gocad TSolid"));
        return finish();
    }

private:
    void readHeader()
    {
        std::string_view line = c.line();
        const int start = c.lineNumber();
        std::size_t open = line.find('{');
        if (open == std::string_view::npos)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "HEADER without '{'"));
        std::string rest(line.substr(open + 1));
        for (;;) {
            const std::size_t close = rest.find('}');
            headerEntry(rest.substr(0, close));
            if (close != std::string::npos)
                return;
            if (!c.next())
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "HEADER block not closed by '}'"));
            refuseEndInBlock("HEADER block", start);
            rest = std::string(c.line());
        }
    }

    void headerEntry(const std::string &entry)
    {
        const std::size_t colon = entry.find(':');
        if (colon == std::string::npos)
            return;
        const std::string key = trim(entry.substr(0, colon));
        const std::string value = trim(std::string_view(entry).substr(colon + 1));
        if (key == "name") {
            mesh.name = value;
        } else if (key.rfind("*tface*", 0) == 0) {
            const std::size_t star = key.find('*', 7);
            long long id = 0;
            if (star == std::string::npos || !parseInt(key.substr(7, star - 7), id))
                return;
            const std::string what = key.substr(star + 1);
            if (what == "name")
                faceNames[id] = value;
            else if (what == "type")
                faceTypes[id] = featureTypeFromGocad(value);
        }
    }

    void skipBlock()
    {
        const int start = c.lineNumber();
        while (c.line().find('}') == std::string_view::npos) {
            if (!c.next())
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "block not closed by '}'"));
            refuseEndInBlock("{ } block", start);
        }
    }

    // A block left open would swallow the END of the object, or the next object.
    void refuseEndInBlock(const char *block, int start) const
    {
        const std::string word = trim(c.line());
        const std::string first = word.substr(0, word.find_first_of(" \t"));
        if (first == "END" || first == "GOCAD")
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "%1 started at line %2 is not closed by '}' before %3"),
                {std::string(block), std::to_string(start), first}});
    }

    int regionIndex(const std::string &name)
    {
        auto it = regionByName.find(name);
        if (it != regionByName.end())
            return it->second;
        mesh.regionNames.push_back(name);
        return regionByName[name] = static_cast<int>(mesh.regionNames.size()) - 1;
    }

    void startVolume(const std::vector<std::string> &t)
    {
        ++volume;
        currentRegion = regionIndex(t.size() > 1 ? t[1] : "region_" + std::to_string(volume + 1));
    }

    long long id(const std::string &token, const char *what) const
    {
        long long v = 0;
        if (!parseInt(token, v))
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "expected %1, found \"%2\""),
                               {what, token}});
        return v;
    }

    void addVertex(const std::vector<std::string> &t)
    {
        if (t.size() < 5)
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "%1 needs an id and three coordinates"),
                {t[0]}});
        const long long vid = id(t[1], "a vertex id");
        const Vec3 p(c.toDouble(t[2], "x"), c.toDouble(t[3], "y"), c.toDouble(t[4], "z"));
        if (MessageText problem = pointProblem(p); !problem.pattern.empty())
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 %2: %3"),
                               {std::string(t[0]), std::string(t[1])},
                               {std::move(problem)}});
        if (!vertices.emplace(vid, Vertex{static_cast<int>(mesh.points.size()), volume}).second)
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "vertex id %1 is used twice"),
                               {std::to_string(vid)}});
        mesh.points.push_back(p);
    }

    void addAtom(const std::vector<std::string> &t)
    {
        if (t.size() < 3)
            c.fail(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "%1 needs an id and the id of the vertex it shares"),
                            {t[0]}});
        const long long vid = id(t[1], "a vertex id"), ref = id(t[2], "a vertex id");
        auto it = vertices.find(ref);
        if (it == vertices.end())
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "%1 %2 refers to vertex %3, which is not defined before"),
                {t[0], std::to_string(vid), std::to_string(ref)}});
        Vertex v = it->second;
        // Same TVOLUME: a crack, i.e. a distinct point at the same place.
        if (!light && v.volume == volume) {
            v = {static_cast<int>(mesh.points.size()), volume};
            mesh.points.push_back(mesh.points[it->second.point]);
        }
        if (!vertices.emplace(vid, v).second)
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "vertex id %1 is used twice"),
                               {std::to_string(vid)}});
    }

    int point(const std::string &token)
    {
        const long long vid = id(token, "a vertex id");
        auto it = vertices.find(vid);
        if (it == vertices.end())
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "vertex %1 is not defined"),
                               {std::to_string(vid)}});
        return it->second.point;
    }

    void addTetra(const std::vector<std::string> &t)
    {
        if (t.size() < 5)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "TETRA needs four vertex ids"));
        Cell cell;
        for (int k = 0; k < 4; ++k) // in file order, so errors name the first bad id
            cell.nodes[k] = point(t[static_cast<std::size_t>(k) + 1]);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < i; ++j)
                if (cell.nodes[i] == cell.nodes[j])
                    c.fail(
                        QT_TRANSLATE_NOOP("stratamesh::Core", "TETRA uses the same vertex twice"));
        mesh.cells.push_back(cell);
        mesh.cellRegion.push_back(currentRegion);
        lastTetraLine = c.lineNumber();
    }

    // "# CTETRA <region> f0 f1 f2 f3" follows its TETRA; it names the region in a LightTSolid.
    void readComment(const std::vector<std::string> &t)
    {
        if (t.size() < 3 || upper(t[1]) != "CTETRA" || mesh.cells.empty()
            || lastTetraLine != c.lineNumber() - 1)
            return;
        if (mesh.cellRegion.back() < 0)
            mesh.cellRegion.back() = regionIndex(t[2]);
    }

    void startFace(const std::vector<std::string> &t)
    {
        const long long k = t.size() > 1 ? id(t[1], "a TFACE id")
                                         : static_cast<long long>(mesh.surfaces.size()) + 1;
        faceIds.push_back(k);
        faceFeatures.push_back(feature.empty() ? "surface" : feature);
        mesh.surfaces.push_back({});
    }

    void addTriangle(const std::vector<std::string> &t)
    {
        if (!inModel || mesh.surfaces.empty())
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL outside a MODEL TFACE"));
        if (t.size() < 4)
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL needs three vertex ids"));
        Triangle tri;
        for (int k = 0; k < 3; ++k)
            tri[k] = point(t[static_cast<std::size_t>(k) + 1]);
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
            c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "TRGL uses the same vertex twice"));
        mesh.triangles.push_back(tri);
        mesh.triangleSurface.push_back(static_cast<int>(mesh.surfaces.size()) - 1);
    }

    VolumeMesh finish()
    {
        if (mesh.name.empty())
            mesh.name = fileStem(c.path());
        std::map<std::string, int> perFeature, seen;
        for (const std::string &f : faceFeatures)
            ++perFeature[f];
        for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
            MeshSurface &surface = mesh.surfaces[s];
            const std::string &f = faceFeatures[s];
            const int k = ++seen[f];
            auto name = faceNames.find(faceIds[s]);
            surface.name = name != faceNames.end() ? name->second
                           : perFeature[f] == 1    ? f
                                                   : f + "_" + std::to_string(k);
            surface.featureName = f;
            auto type = faceTypes.find(faceIds[s]);
            surface.type = type != faceTypes.end() ? type->second : FeatureType::Unknown;
        }
        for (int &r : mesh.cellRegion)
            if (r < 0)
                r = regionIndex("untagged");
        if (mesh.zPositiveDepth)
            for (Vec3 &p : mesh.points)
                p.z() = -p.z();
        mesh.regionBoundaries = regionSidesFromCells(mesh);
        try {
            validateMesh(mesh);
        } catch (const InputError &e) {
            throw FileError(c.path(), 0, causeOf(e));
        }
        return std::move(mesh);
    }

    struct Vertex {
        int point = -1;
        int volume = -1;
    };

    TextCursor c;
    VolumeMesh mesh;
    bool light = false;
    bool inModel = false;
    int volume = -1;
    int currentRegion = -1;
    int lastTetraLine = -10;
    std::string feature;
    std::unordered_map<long long, Vertex> vertices;
    std::map<std::string, int> regionByName;
    std::map<long long, std::string> faceNames;
    std::map<long long, FeatureType> faceTypes;
    std::vector<long long> faceIds;
    std::vector<std::string> faceFeatures;
};

} // namespace

VolumeMesh readGocadTSolid(const std::string &path)
{
    return TSolidParser(path).run();
}

} // namespace stratamesh
