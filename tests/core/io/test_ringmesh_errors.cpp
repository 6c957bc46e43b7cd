// RINGMesh .gm input on archives built here, byte by byte, with minizip and zlib: a valid unit
// cube, then one damage per case (corrupt zip, missing entity file, truncated or garbled GeoFile
// chunk, counts that disagree with mesh_entities.txt). Every case must give a FileError naming
// the archive, the entry and the cause; the address space is capped so that an allocation from a
// lying size field fails the test instead of passing unnoticed.
#include "common/error.h"
#include "io/model_reader.h"
#include "io/ringmesh_reader.h"
#include "io/ringmesh_writer.h"
#include "model/region_volume.h"
#include "model/topology.h"
#include "support/sanitizer.h"

#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>
#include <zip.h>
#include <zlib.h>

#include <cstring>
#include <fstream>
#include <map>

using namespace stratamesh;

namespace {

// --- A GeoFile encoder written from the format description, independent of core/io. ---

void u32(std::string &out, std::uint32_t v)
{
    out.append(reinterpret_cast<const char *>(&v), 4);
}
void u64(std::string &out, std::uint64_t v)
{
    out.append(reinterpret_cast<const char *>(&v), 8);
}
void str(std::string &out, const std::string &s)
{
    u32(out, std::uint32_t(s.size()));
    out += s;
}
std::string chunk(const char *cls, const std::string &body)
{
    std::string out(cls, 4);
    u64(out, body.size());
    return out + body;
}
std::string atts(const std::string &set, std::uint32_t items)
{
    std::string b;
    str(b, set);
    u32(b, items);
    return chunk("ATTS", b);
}
std::string attr(const std::string &set, const std::string &name, const std::string &type,
                 std::uint32_t size, std::uint32_t dim, const std::string &data)
{
    std::string b;
    str(b, set);
    str(b, name);
    str(b, type);
    u32(b, size);
    u32(b, dim);
    return chunk("ATTR", b + data);
}

std::string gzipped(const std::string &raw)
{
    z_stream z{};
    deflateInit2(&z, 6, Z_DEFLATED, 31, 8, Z_DEFAULT_STRATEGY);
    std::string out(deflateBound(&z, uLong(raw.size())) + 32, '\0');
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(raw.data()));
    z.avail_in = uInt(raw.size());
    z.next_out = reinterpret_cast<Bytef *>(out.data());
    z.avail_out = uInt(out.size());
    deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

// Face f of the unit cube as two triangles with outward normals (the region is on their
// negative side).
struct Face {
    std::vector<double> xyz; // 4 points
};
std::vector<Face> cubeFaces()
{
    const double p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    std::vector<Face> faces;
    for (const auto &q : quads) {
        Face f;
        for (int k = 0; k < 4; ++k)
            f.xyz.insert(f.xyz.end(), {p[q[k]][0], p[q[k]][1], p[q[k]][2]});
        faces.push_back(f);
    }
    return faces;
}

std::string bytesOf(const std::vector<double> &v)
{
    return {reinterpret_cast<const char *>(v.data()), v.size() * 8};
}
std::string bytesOf(const std::vector<std::uint32_t> &v)
{
    return {reinterpret_cast<const char *>(v.data()), v.size() * 4};
}

std::string head()
{
    std::string b;
    str(b, "GEOGRAM");
    str(b, "1.0");
    return chunk("HEAD", b);
}

// The uncompressed GeoFile of one cube face: 4 vertices, 2 triangles (0 1 2), (0 2 3).
std::string faceGeoFile(const Face &f, std::uint32_t corners = 6)
{
    std::vector<std::uint32_t> cv = {0, 1, 2, 0, 2, 3};
    cv.resize(corners, 0);
    return head() + atts("GEO::Mesh::vertices", 4)
           + attr("GEO::Mesh::vertices", "point", "double", 8, 3, bytesOf(f.xyz))
           + atts("GEO::Mesh::facets", 2) + atts("GEO::Mesh::facet_corners", corners)
           + attr("GEO::Mesh::facet_corners", "GEO::Mesh::facet_corners::corner_vertex", "index_t",
                  4, 1, bytesOf(cv));
}

std::string meshEntities(int surfaces = 6)
{
    std::string s = "Version 2\nGeoModel name cube\nNb Corner 0\nNb Line 0\nNb Surface "
                    + std::to_string(surfaces) + "\nNb Region 1\n";
    for (int i = 0; i < 6; ++i)
        s += "Surface " + std::to_string(i) + " No_name GeogramSurfaceMesh\nboundary \n";
    s += "Region 0 inside GeogramVolumeMesh\n-0 -1 -2 -3 -4 -5 \nUniverse \n+0 +1 +2 +3 +4 +5 \n";
    return s;
}

const char *kGeology = "Nb Interface 1\nNb Layer 1\nInterface 0 cube boundary\n0 1 2 3 4 5 \n"
                       "Layer 0 all no_geological_feature\n0 \n";

using Entries = std::map<std::string, std::string>; // name → stored bytes (already gzipped)

Entries cubeEntries()
{
    Entries e;
    e["mesh_entities.txt"] = meshEntities();
    e["geological_entities.txt"] = kGeology;
    const std::vector<Face> faces = cubeFaces();
    for (int i = 0; i < 6; ++i)
        e["Surface_" + std::to_string(i) + ".geogram"] = gzipped(faceGeoFile(faces[i]));
    return e;
}

void writeZip(const QString &path, const Entries &entries)
{
    zipFile zf = zipOpen64(path.toLocal8Bit().constData(), APPEND_STATUS_CREATE);
    QVERIFY(zf);
    for (const auto &[name, bytes] : entries) {
        zip_fileinfo info{};
        QCOMPARE(zipOpenNewFileInZip64(zf, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                                       Z_DEFLATED, Z_DEFAULT_COMPRESSION, 0),
                 ZIP_OK);
        QCOMPARE(zipWriteInFileInZip(zf, bytes.data(), unsigned(bytes.size())), ZIP_OK);
        QCOMPARE(zipCloseFileInZip(zf), ZIP_OK);
    }
    QCOMPARE(zipClose(zf, nullptr), ZIP_OK);
}

// The FileError message of reading `path`, or "" when it reads fine.
std::string readError(const QString &path)
{
    try {
        readModel(path.toStdString());
        readRingMeshVolume(path.toStdString());
    } catch (const FileError &e) {
        return e.what();
    }
    return {};
}

#define EXPECT_FILE_ERROR(path, entry, cause)                                                      \
    do {                                                                                           \
        const std::string message = readError(path);                                               \
        qInfo("%s", message.c_str());                                                              \
        QVERIFY2(!message.empty(), "no FileError");                                                \
        QVERIFY2(message.find((path).toStdString() + ":" + std::string(entry)) == 0,               \
                 message.c_str());                                                                 \
        QVERIFY2(message.find(cause) != std::string::npos, message.c_str());                       \
    } while (0)

} // namespace

class TestRingMeshErrors : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString file(const char *name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // AddressSanitizer maps terabytes of shadow memory: no address-space cap under it.
        if (stratamesh::test::kSanitized)
            return;
        const rlim_t cap = rlim_t(2) << 30; // far above what these tiny archives need
        rlimit limit{cap, cap};
        QCOMPARE(setrlimit(RLIMIT_AS, &limit), 0);
    }

    // The hand-made archive is valid: the damaged ones below fail for their damage only.
    void validCube()
    {
        const QString path = file("cube.gm");
        writeZip(path, cubeEntries());
        QCOMPARE(readError(path), std::string());
        const Model m = readModel(path.toStdString());
        QCOMPARE(m.name, std::string("cube"));
        QCOMPARE(m.surfaces.size(), std::size_t(6));
        QCOMPARE(m.surfaces[0].name, std::string("cube_1"));
        QCOMPARE(m.surfaces[5].name, std::string("cube_6"));
        QCOMPARE(m.surfaces[3].featureName, std::string("cube"));
        QCOMPARE(int(m.surfaces[3].type), int(FeatureType::Boundary));
        QCOMPARE(m.regions.size(), std::size_t(1));
        QCOMPARE(m.regions[0].name, std::string("inside"));
        QCOMPARE(m.layers.size(), std::size_t(1));
        QCOMPARE(m.layers[0].regions, std::vector<int>{0});
        QCOMPARE(m.universe.size(), std::size_t(6));
        QVERIFY(m.universe[2].positive);
        QCOMPARE(regionVolumes(m)[0], 1.0); // outward triangles, region on their negative side
        QCOMPARE(universeVolume(m), -1.0);
        const Model t = recoverTopology(m);
        QCOMPARE(t.lines.size(), std::size_t(12));
        QCOMPARE(t.corners.size(), std::size_t(8));
    }

    void roundTrip()
    {
        const QString a = file("cube.gm"), b = file("cube_copy.gm");
        writeZip(a, cubeEntries());
        const Model first = readModel(a.toStdString());
        writeRingMeshModel(first, b.toStdString());
        const Model second = readModel(b.toStdString());
        QCOMPARE(second.name, first.name);
        QCOMPARE(second.surfaces.size(), first.surfaces.size());
        for (std::size_t s = 0; s < first.surfaces.size(); ++s) {
            QCOMPARE(second.surfaces[s].name, first.surfaces[s].name);
            QCOMPARE(second.surfaces[s].featureName, first.surfaces[s].featureName);
            QCOMPARE(int(second.surfaces[s].type), int(first.surfaces[s].type));
            QCOMPARE(second.surfaces[s].triangles, first.surfaces[s].triangles);
            QVERIFY(second.surfaces[s].vertices == first.surfaces[s].vertices);
        }
        QVERIFY(second.regions[0].boundaries == first.regions[0].boundaries);
        QVERIFY(second.universe == first.universe);
        QCOMPARE(second.layers.size(), std::size_t(1));
        // 8 corners and 12 lines from the recovered topology, each with its GeoFile.
        const Model t = recoverTopology(second);
        QCOMPARE(t.corners.size(), std::size_t(8));
    }

    void corruptZip()
    {
        const QString path = file("garbage.gm");
        std::ofstream(path.toStdString(), std::ios::binary) << std::string(5000, '\x5a');
        const std::string message = readError(path);
        QVERIFY2(message.find(path.toStdString() + ": ") == 0, message.c_str());
        QVERIFY2(message.find("not a readable zip archive") != std::string::npos, message.c_str());
    }

    void truncatedZip()
    {
        const QString whole = file("whole.gm"), cut = file("cut.gm");
        writeZip(whole, cubeEntries());
        std::ifstream in(whole.toStdString(), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(cut.toStdString(), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
        const std::string message = readError(cut);
        QVERIFY2(message.find(cut.toStdString() + ": ") == 0, message.c_str());
        QVERIFY2(message.find("zip") != std::string::npos, message.c_str());
    }

    void missingEntityFile()
    {
        const QString path = file("missing.gm");
        Entries e = cubeEntries();
        e.erase("Surface_3.geogram");
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_3.geogram", "entry missing from the archive");
    }

    void missingMeshEntities()
    {
        const QString path = file("no_entities.gm");
        Entries e = cubeEntries();
        e.erase("mesh_entities.txt");
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "mesh_entities.txt", "entry missing");
    }

    void truncatedChunk()
    {
        const QString path = file("truncated_chunk.gm");
        Entries e = cubeEntries();
        const std::string raw = faceGeoFile(cubeFaces()[1]);
        e["Surface_1.geogram"] = gzipped(raw.substr(0, raw.size() - 30)); // inside corner_vertex
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_1.geogram", "chunk 'ATTR' claims");
    }

    void truncatedGzip()
    {
        const QString path = file("truncated_gzip.gm");
        Entries e = cubeEntries();
        const std::string gz = e["Surface_2.geogram"];
        e["Surface_2.geogram"] = gz.substr(0, gz.size() / 2);
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_2.geogram", "truncated gzip stream");
    }

    void garbledChunkSize()
    {
        const QString path = file("garbled_size.gm");
        Entries e = cubeEntries();
        std::string raw = faceGeoFile(cubeFaces()[4]);
        // The size field of the first ATTR chunk (the points) becomes 2^62.
        const std::size_t at = raw.find("ATTR");
        QVERIFY(at != std::string::npos);
        const std::uint64_t huge = std::uint64_t(1) << 62;
        std::memcpy(&raw[at + 4], &huge, 8);
        e["Surface_4.geogram"] = gzipped(raw);
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_4.geogram", "claims 4611686018427387904 bytes");
    }

    void hugeItemCount()
    {
        const QString path = file("huge_items.gm");
        Entries e = cubeEntries();
        std::string raw = faceGeoFile(cubeFaces()[0]);
        // 2^32 - 1 vertices announced, 4 stored.
        const std::size_t at = raw.find("GEO::Mesh::vertices") + std::strlen("GEO::Mesh::vertices");
        const std::uint32_t items = 0xffffffffu;
        std::memcpy(&raw[at], &items, 4);
        e["Surface_0.geogram"] = gzipped(raw);
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_0.geogram", "is larger than its chunk");
    }

    void countMoreThanDescribed()
    {
        const QString path = file("count.gm");
        Entries e = cubeEntries();
        e["mesh_entities.txt"] = meshEntities(7);
        writeZip(path, e);
        EXPECT_FILE_ERROR(path,
                          "mesh_entities.txt:", "'Nb Surface 7' but Surface 6 is never described");
    }

    void entryBeyondCount()
    {
        const QString path = file("extra.gm");
        Entries e = cubeEntries();
        e["Surface_6.geogram"] = e["Surface_0.geogram"];
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_6.geogram",
                          "no such entity: mesh_entities.txt says 'Nb Surface 6'");
    }

    void cornersDisagreeWithFacets()
    {
        const QString path = file("corners.gm");
        Entries e = cubeEntries();
        e["Surface_2.geogram"] = gzipped(faceGeoFile(cubeFaces()[2], 5));
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "Surface_2.geogram",
                          "2 items of 'GEO::Mesh::facets' need 6 corners, the file has 5");
    }

    void interfaceChildBeyondCount()
    {
        const QString path = file("interface.gm");
        Entries e = cubeEntries();
        e["geological_entities.txt"] =
            "Nb Interface 1\nInterface 0 cube boundary\n0 1 2 3 4 5 6 \n";
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "geological_entities.txt:3", "Surface 6 as child");
    }

    // Cut anywhere, a GeoFile is an error naming its entry: a chunk runs past the end, or what
    // was cut off (an attribute, the facets) is missing.
    void everyTruncation()
    {
        const QString path = file("cut_anywhere.gm");
        const std::string raw = faceGeoFile(cubeFaces()[0]);
        for (std::size_t n = 0; n < raw.size(); n += 7) {
            Entries e = cubeEntries();
            e["Surface_0.geogram"] = gzipped(raw.substr(0, n));
            writeZip(path, e);
            const std::string message = readError(path);
            QVERIFY2(message.find(path.toStdString() + ":Surface_0.geogram: ") == 0,
                     qPrintable(QString("cut at %1: '%2'").arg(n).arg(message.c_str())));
        }
    }

    // Random damage inside a GeoFile reads or fails with a FileError; nothing else escapes, and
    // nothing allocates beyond the address-space cap.
    void randomByteFlips()
    {
        const QString path = file("flipped.gm");
        const std::string raw = faceGeoFile(cubeFaces()[3]);
        std::uint32_t state = 12345;
        const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
        int errors = 0;
        for (int round = 0; round < 300; ++round) {
            std::string damaged = raw;
            const int flips = 1 + int(next() % 4);
            for (int f = 0; f < flips; ++f)
                damaged[next() % damaged.size()] = char(next() >> 24);
            Entries e = cubeEntries();
            e["Surface_3.geogram"] = gzipped(damaged);
            writeZip(path, e);
            try {
                readModel(path.toStdString());
                readRingMeshVolume(path.toStdString());
            } catch (const FileError &) {
                ++errors;
            }
        }
        qInfo("%d of 300 damaged files rejected, the rest read", errors);
        QVERIFY(errors > 0);
    }

    void regionSideBeyondCount()
    {
        const QString path = file("side.gm");
        Entries e = cubeEntries();
        std::string text = meshEntities();
        text.replace(text.find("-5 \n"), 4, "-9 \n");
        e["mesh_entities.txt"] = text;
        writeZip(path, e);
        EXPECT_FILE_ERROR(path, "mesh_entities.txt:",
                          "Region 0 has Surface 9 as boundary, but 'Nb Surface' is 6");
    }
};

QTEST_GUILESS_MAIN(TestRingMeshErrors)
#include "test_ringmesh_errors.moc"
