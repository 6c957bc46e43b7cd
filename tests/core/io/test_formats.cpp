// The format table (core/io/formats.h): every capability it claims for a row, kept or dropped, is
// measured by writing a model and volume meshes built in code through that row and reading them
// back; the entry points (readModel, readVolumeMesh, exportModel, exportVolumeMesh and their
// is*File predicates) agree with it; the extension helper, the dialog filters and the "drops"
// query behave as documented.
#include "common/error.h"
#include "io/formats.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/ringmesh_reader.h"
#include "io/surface_mesh_writer.h"
#include "mesh/model_conversion.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "test_roundtrip_meshes.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

// A box cut by one horizon (two regions, box and horizon surfaces, contact lines and corners),
// moved by an offset that 32-bit floats cannot hold, so that precision losses show.
Model offsetBox()
{
    LayeredBoxParams p;
    p.horizons = 1;
    p.edgeLength = 250.0;
    Model m = layeredBox(p);
    const Vec3 offset(1.0 / 3.0, 2.0 / 7.0, 0.1);
    for (Surface &s : m.surfaces)
        for (Vec3 &v : s.vertices)
            v += offset; // the same doubles in, the same doubles out: still conformal
    return recoverTopology(m);
}

// The mesh of test_roundtrip_meshes.h keeping only its cells of the given types.
VolumeMesh cellsOfTypes(const std::set<CellType> &types)
{
    VolumeMesh m = hybridMesh();
    VolumeMesh out = m;
    out.cells.clear();
    out.cellRegion.clear();
    out.cellQuality.clear();
    for (std::size_t c = 0; c < m.cells.size(); ++c)
        if (types.count(m.cells[c].type)) {
            out.cells.push_back(m.cells[c]);
            out.cellRegion.push_back(m.cellRegion[c]);
            out.cellQuality.push_back(m.cellQuality[c]);
        }
    return out;
}

// Triangles as text of their corner coordinates (17 digits), whatever the numbering.
std::multiset<std::string> triangleTexts(const Model &m)
{
    std::multiset<std::string> out;
    for (const Surface &s : m.surfaces)
        for (const Triangle &t : s.triangles) {
            std::vector<std::string> corners{text(s.vertices[t[0]]), text(s.vertices[t[1]]),
                                             text(s.vertices[t[2]])};
            std::sort(corners.begin(), corners.end());
            out.insert(corners[0] + corners[1] + corners[2]);
        }
    return out;
}

double largestCoordinateError(const Model &a, const Model &b)
{
    // Every vertex of b near some vertex of a: the geometry is there, at the format's precision.
    std::vector<Vec3> pa;
    for (const Surface &s : a.surfaces)
        pa.insert(pa.end(), s.vertices.begin(), s.vertices.end());
    double worst = 0.0;
    for (const Surface &s : b.surfaces)
        for (const Vec3 &v : s.vertices) {
            double best = std::numeric_limits<double>::infinity();
            for (const Vec3 &p : pa)
                best = std::min(best, (p - v).norm());
            worst = std::max(worst, best);
        }
    return worst;
}

std::set<std::string> surfaceNames(const Model &m)
{
    std::set<std::string> out;
    for (const Surface &s : m.surfaces)
        out.insert(s.name);
    return out;
}

std::multiset<std::pair<std::string, FeatureType>> namedTypes(const Model &m)
{
    std::multiset<std::pair<std::string, FeatureType>> out;
    for (const Surface &s : m.surfaces)
        out.insert({s.name, s.type});
    return out;
}

std::map<std::string, std::set<std::pair<std::string, bool>>> modelSides(const Model &m)
{
    std::vector<std::string> regions, surfaces;
    std::vector<std::vector<RegionSide>> sides;
    for (const Region &r : m.regions) {
        regions.push_back(r.name);
        sides.push_back(r.boundaries);
    }
    for (const Surface &s : m.surfaces)
        surfaces.push_back(s.name);
    return namedSides(regions, sides, surfaces);
}

Model readBack(const FileFormat &f, const std::string &path)
{
    return f.readsModel() ? f.readModel(path) : modelFromMesh(f.readMesh(path));
}

QString rowName(const FileFormat &f)
{
    return QString::fromLatin1(f.extension);
}

} // namespace

class TestFormats : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    std::string pathFor(const char *stem, const FileFormat &f) const
    {
        return m_dir.filePath(QString::fromLatin1(stem) + QString::fromLatin1(f.extension))
            .toStdString();
    }

private slots:
    void extensionHelper()
    {
        QCOMPARE(fileExtension("a/b.ML"), std::string(".ml"));
        QCOMPARE(fileExtension("B.Vtu"), std::string(".vtu"));
        QCOMPARE(fileExtension("a/b.tar.GZ"), std::string(".gz"));
        QCOMPARE(fileExtension("a.d/b"), std::string());
        QCOMPARE(fileExtension("a/.ml"), std::string()); // a hidden file, not an extension
        QCOMPARE(fileExtension("noext"), std::string());
        QCOMPARE(fileExtension(""), std::string());
        QCOMPARE(fileStem("a/b.tar.gz"), std::string("b.tar"));
        QCOMPARE(fileStem("dir.d/model"), std::string("model"));
        QCOMPARE(fileStem("a/.ml"), std::string(".ml")); // never an empty name
        QCOMPARE(fileStem("modelA1.ML"), std::string("modelA1"));
        QVERIFY(findFormat("x/Y.MSH") != nullptr);
        QCOMPARE(std::string(findFormat("x/Y.MSH")->extension), std::string(".msh"));
        QVERIFY(findFormat("y.xyz") == nullptr);
        QVERIFY(findFormat("msh") == nullptr);
        QVERIFY(isRingMeshFile("a/B.GM"));
        QVERIFY(!isRingMeshFile("a/b.gmx"));
    }

    void tableIsConsistent()
    {
        std::set<std::string> seen;
        for (const FileFormat &f : fileFormats()) {
            const std::string ext = f.extension;
            QVERIFY2(ext.size() >= 2 && ext[0] == '.', f.extension);
            QVERIFY2(fileExtension("x" + ext) == ext, f.extension); // lower case, one dot
            QVERIFY2(seen.insert(ext).second, f.extension);
            QVERIFY2(std::string(f.name).size() > 2, f.extension);
            // Whatever is written can be read back, so every claim below is measurable.
            QVERIFY2(!f.writes() || f.readsModel() || f.readsMesh(), f.extension);
            QVERIFY2(f.readsModel() || f.readsMesh(), f.extension);
            // A file that may hold cells has a mesh reader and a mesh writer.
            if (f.holds == FormatHolds::VolumeMesh)
                QVERIFY2(f.readsMesh() && f.writeMesh != nullptr, f.extension);
            if (f.holds == FormatHolds::SingleSurface)
                QVERIFY2(!f.keeps.severalSurfaces && !f.keeps.regions, f.extension);
            if (f.needsCells)
                QVERIFY2(f.writeMesh != nullptr && f.writeModel == nullptr && f.keeps.tetrahedra,
                         f.extension);
            if (f.keeps.pyramidsPrisms)
                QVERIFY2(f.keeps.tetrahedra, f.extension);
        }
        for (const char *ext : {".ml", ".ts", ".gm", ".so", ".msh", ".vtu", ".vtk", ".vtp", ".obj",
                                ".off", ".stl", ".ply"})
            QVERIFY2(seen.count(ext), ext);
    }

    // The entry points answer from the table, row by row.
    void entryPointsFollowTheTable()
    {
        for (const FileFormat &f : fileFormats()) {
            const std::string path = std::string("dir/file") + f.extension;
            QCOMPARE(isReadableModelFile(path), f.readsModel());
            QCOMPARE(isMeshReaderFile(path), f.readsMesh());
            QCOMPARE(isExportFile(path), f.writes());
            QCOMPARE(isVolumeMeshFile(path), f.holds == FormatHolds::VolumeMesh);
            QCOMPARE(isSurfaceMeshFile(path), f.holds == FormatHolds::SingleSurface);
            QCOMPARE(isFileFor(path, FormatUse::Export), f.writes());
        }
        QVERIFY(!isExportFile("a.xyz") && !isReadableModelFile("a.xyz"));
        // The refusals list exactly what the table serves.
        try {
            readModel(m_dir.filePath("m.xyz").toStdString());
            QFAIL("readModel accepted .xyz");
        } catch (const FileError &e) {
            const std::string list = extensionList(FormatUse::ReadModel);
            QVERIFY2(std::string(e.what()).find("(expected " + list + ")") != std::string::npos,
                     e.what());
            QStringList listed = QString::fromStdString(list).split(QStringLiteral(", "));
            listed += listed.takeLast().split(QStringLiteral(" or "));
            for (const FileFormat &f : fileFormats())
                QCOMPARE(listed.contains(rowName(f)), f.readsModel());
        }
        QVERIFY_THROWS_EXCEPTION(FileError, readVolumeMesh("m.ml"));
        QVERIFY_THROWS_EXCEPTION(FileError, exportModel(offsetBox(), "m.xyz"));
        // A surface model cannot become a TSolid: InputError, and no file.
        const std::string so = m_dir.filePath("box.so").toStdString();
        QVERIFY_THROWS_EXCEPTION(InputError, exportModel(offsetBox(), so));
        QVERIFY(!QFile::exists(QString::fromStdString(so)));
    }

    // A surface model through every row that takes one: each claim of FormatKeeps but the cell
    // ones is measured and must equal the table, kept as well as dropped.
    void modelRoundTrip_data()
    {
        QTest::addColumn<int>("row");
        for (std::size_t r = 0; r < fileFormats().size(); ++r) {
            const FileFormat &f = fileFormats()[r];
            if (f.writes() && !f.needsCells)
                QTest::newRow(f.extension) << int(r);
        }
    }

    void modelRoundTrip()
    {
        QFETCH(int, row);
        const FileFormat &f = fileFormats()[std::size_t(row)];
        const Model box = offsetBox();
        QVERIFY(box.surfaces.size() > 2 && box.regions.size() == 2 && !box.lines.empty()
                && !box.corners.empty());
        const std::string path = pathFor("written", f);

        // severalSurfaces: the whole model is written, or refused (InputError) and one surface is.
        Model written = box;
        bool several = true;
        try {
            exportModel(box, path);
        } catch (const InputError &) {
            several = false;
            ExportOptions one;
            one.surface = 0;
            exportModel(box, path, one);
            written.surfaces = {box.surfaces[0]};
        }
        const Model back = readBack(f, path);
        several = several && back.surfaces.size() == box.surfaces.size();
        QCOMPARE(several, f.keeps.severalSurfaces);
        QCOMPARE(back.triangleCount(), written.triangleCount());

        const bool exact = triangleTexts(back) == triangleTexts(written);
        QCOMPARE(exact, f.keeps.exactCoordinates);
        // Lossy or not, the geometry is there (floats: 1e-7 of coordinates near 1000).
        QVERIFY2(largestCoordinateError(written, back) < 1e-3,
                 qPrintable(QString::number(largestCoordinateError(written, back))));

        const bool names = surfaceNames(back) == surfaceNames(box);
        QCOMPARE(names, f.keeps.surfaceNames);
        // Types matched by name where names survive; a lost name loses its type with it.
        const bool types = namedTypes(back) == namedTypes(box);
        QCOMPARE(types, f.keeps.featureTypes);
        const bool regions =
            back.regions.size() == box.regions.size() && modelSides(back) == modelSides(box);
        QCOMPARE(regions, f.keeps.regions);

        // Lines and corners: recovered from the file's surfaces, and stated as named edges and
        // corner points where the format is read as a mesh.
        const Model topology = recoverTopology(back);
        bool lines = topology.lines.size() == box.lines.size()
                     && topology.corners.size() == box.corners.size();
        if (lines && f.readsMesh() && !isRingMeshFile(path)) {
            const VolumeMesh mesh = f.readMesh(path);
            lines = mesh.lineNames.size() == box.lines.size()
                    && mesh.corners.size() == box.corners.size();
        }
        QCOMPARE(lines, f.keeps.linesAndCorners);
    }

    // Volume meshes through every writable row: tetrahedra, then pyramids and prisms, kept
    // (read back with their counts and regions) or dropped (refused, or reported as dropped).
    void meshRoundTrip_data()
    {
        QTest::addColumn<int>("row");
        for (std::size_t r = 0; r < fileFormats().size(); ++r)
            if (fileFormats()[r].writes())
                QTest::newRow(fileFormats()[r].extension) << int(r);
    }

    void meshRoundTrip()
    {
        QFETCH(int, row);
        const FileFormat &f = fileFormats()[std::size_t(row)];
        auto keeps = [&](const VolumeMesh &mesh, const char *stem) {
            const std::string path = pathFor(stem, f);
            try {
                if (exportVolumeMesh(mesh, path).cellsDropped > 0)
                    return false;
            } catch (const InputError &) {
                return false;
            }
            if (!f.readsMesh())
                return false;
            const VolumeMesh back = f.readMesh(path);
            for (CellType t : {CellType::Tet, CellType::Pyramid, CellType::Prism})
                if (back.countCells(t) != mesh.countCells(t))
                    return false;
            // Cells keep their region names too.
            std::multiset<std::string> ra, rb;
            for (int r : mesh.cellRegion)
                ra.insert(mesh.regionNames[std::size_t(r)]);
            for (int r : back.cellRegion)
                rb.insert(r < 0 ? std::string() : back.regionNames[std::size_t(r)]);
            return ra == rb;
        };
        const VolumeMesh tets = cellsOfTypes({CellType::Tet});
        QVERIFY(tets.countCells(CellType::Tet) == 2 && tets.cells.size() == 2);
        QCOMPARE(keeps(tets, "tets"), f.keeps.tetrahedra);
        const VolumeMesh hybrid = hybridMesh();
        QVERIFY(hybrid.countCells(CellType::Pyramid) > 0 && hybrid.countCells(CellType::Prism) > 0);
        QCOMPARE(keeps(hybrid, "hybrid"), f.keeps.pyramidsPrisms);
        QCOMPARE(formatServes(f, FormatUse::WriteVolumeMesh),
                 f.writeMesh != nullptr && f.keeps.tetrahedra);
    }

    // A format that holds only volume meshes (TSolid) takes no surface model: its surface,
    // region and line claims are measured on a tet mesh instead.
    void cellOnlyFormatsKeepTheirMetadata()
    {
        VolumeMesh tets = cellsOfTypes({CellType::Tet});
        // Only what the tets bound: the interface triangles, their line and corners.
        tets.triangles = {{4, 5, 7}, {5, 6, 7}};
        tets.triangleSurface = {0, 0};
        tets.surfaces = {{"interface", "H1", FeatureType::Horizon}};
        int rows = 0;
        for (const FileFormat &f : fileFormats()) {
            if (!f.needsCells)
                continue;
            ++rows;
            const std::string path = pathFor("metadata", f);
            exportVolumeMesh(tets, path);
            const VolumeMesh back = f.readMesh(path);
            QCOMPARE(back.countCells(CellType::Tet), tets.countCells(CellType::Tet));
            QCOMPARE(back.surfaces.size() == tets.surfaces.size()
                         && back.triangles.size() == tets.triangles.size(),
                     true);
            QCOMPARE(back.surfaces[0].name == "interface", f.keeps.surfaceNames);
            QCOMPARE(back.surfaces[0].type == FeatureType::Horizon, f.keeps.featureTypes);
            std::set<std::string> regions(back.regionNames.begin(), back.regionNames.end());
            QCOMPARE(regions == std::set<std::string>{"upper"}
                         || back.regionNames == tets.regionNames,
                     f.keeps.regions);
            QCOMPARE(back.lineNames == tets.lineNames && back.corners.size() == tets.corners.size()
                         && back.edges.size() == tets.edges.size(),
                     f.keeps.linesAndCorners);
            std::multiset<std::string> pa, pb;
            for (const Vec3 &p : tets.points)
                pa.insert(text(p));
            for (const Vec3 &p : back.points)
                pb.insert(text(p));
            QCOMPARE(std::includes(pa.begin(), pa.end(), pb.begin(), pb.end()),
                     f.keeps.exactCoordinates);
        }
        QVERIFY(rows > 0);
    }

    void dialogFilters()
    {
        const std::string filter = fileDialogFilter(FormatUse::ReadModel, "Models", "All files");
        const QStringList entries = QString::fromStdString(filter).split(QStringLiteral(";;"));
        const std::vector<const FileFormat *> readable = formatsFor(FormatUse::ReadModel);
        QCOMPARE(entries.size(), int(readable.size()) + 2);
        QCOMPARE(entries.last(), QStringLiteral("All files (*)"));
        QVERIFY(entries.first().startsWith(QStringLiteral("Models (*.ml *.ts ")));
        for (const FileFormat *f : readable) {
            QVERIFY(entries.first().contains(QStringLiteral("*") + rowName(*f)));
            QVERIFY(entries.contains(QString::fromLatin1(f->name) + QStringLiteral(" (*")
                                     + rowName(*f) + QStringLiteral(")")));
        }
        // STL is read as a mesh only: not offered to open a model.
        QVERIFY(!entries.first().contains(QStringLiteral("*.stl")));
        // No label: no aggregate entry.
        const QStringList save =
            QString::fromStdString(fileDialogFilter(FormatUse::WriteModel, {}, {}))
                .split(QStringLiteral(";;"));
        QCOMPARE(save.size(), int(formatsFor(FormatUse::WriteModel).size()));
        QVERIFY(save.first().startsWith(QStringLiteral("Gocad Model3d (*.ml)")));
        for (const QString &e : save)
            QVERIFY2(!e.contains(QStringLiteral(".obj")) && !e.contains(QStringLiteral(".so")),
                     qPrintable(e));

        // The chosen entry's extension is added when the typed name has no usable one.
        QCOMPARE(withFormatExtension("d/out", FormatUse::WriteModel, "RINGMesh GeoModel (*.gm)"),
                 std::string("d/out.gm"));
        QCOMPARE(withFormatExtension("d/out.TS", FormatUse::WriteModel, "Gocad Model3d (*.ml)"),
                 std::string("d/out.TS"));
        QCOMPARE(withFormatExtension("d/out.obj", FormatUse::WriteModel, ""),
                 std::string("d/out.obj.ml"));
        QCOMPARE(withFormatExtension("d/out", FormatUse::WriteVolumeMesh, "Gmsh MSH (*.msh)"),
                 std::string("d/out.msh"));
        // An entry of another use does not pick a format that cannot serve this one.
        QCOMPARE(withFormatExtension("d/out", FormatUse::WriteModel, "Gocad TSolid (*.so)"),
                 std::string("d/out.ml"));
    }

    void dropsFollowTheClaims()
    {
        auto has = [](const std::vector<std::string> &list, const std::string &what) {
            return std::find(list.begin(), list.end(), what) != list.end();
        };
        QVERIFY(has(whatFormatDrops("a.msh", false), "feature types"));
        QVERIFY(!has(whatFormatDrops("a.msh", false), "regions"));
        QVERIFY(whatFormatDrops("a.ml", false).empty());
        QVERIFY(has(whatFormatDrops("a.ml", true), "volume cells"));
        QVERIFY(has(whatFormatDrops("a.vtp", true), "volume cells"));
        QVERIFY(has(whatFormatDrops("a.so", true), "pyramids and prisms"));
        QVERIFY(has(whatFormatDrops("A.STL", false), "double precision (coordinates as 32-bit "
                                                     "floats)"));
        QVERIFY(whatFormatDrops("a.xyz", false).empty());
        for (const FileFormat &f : fileFormats()) {
            const FormatKeeps &k = f.keeps;
            const bool all = k.severalSurfaces && k.surfaceNames && k.featureTypes && k.regions
                             && k.linesAndCorners && k.exactCoordinates;
            QCOMPARE(whatFormatDrops(std::string("x") + f.extension, false).empty(), all);
            QCOMPARE(whatFormatDrops(std::string("x") + f.extension, true).empty(),
                     all && k.tetrahedra && k.pyramidsPrisms);
        }
    }

    // The options an export dialog offers per row are the ones its writer reads: the surface
    // index changes what a model writes, -1 writes them all where claimed, and the Gmsh version
    // changes the file.
    void optionsFollowTheWriters()
    {
        const Model box = offsetBox();
        for (const FileFormat &f : fileFormats()) {
            if (!f.writes() || f.needsCells)
                continue;
            const auto written = [&](const char *stem, const ExportOptions &o) {
                const std::string path = pathFor(stem, f);
                exportModel(box, path, o);
                return readBack(f, path);
            };
            ExportOptions first, second, all, v22;
            first.surface = 0;
            second.surface = 1;
            v22.surface = 0;
            v22.gmsh.version = GmshWriteOptions::Version::V22;
            const Model a = written("opt_first", first);
            const Model b = written("opt_second", second);
            const bool surface = a.surfaces.size() == 1 && b.surfaces.size() == 1
                                 && a.triangleCount() == box.surfaces[0].triangles.size()
                                 && b.triangleCount() == box.surfaces[1].triangles.size();
            QVERIFY2(surface == f.options.surface, f.extension);
            bool allWritten = true;
            try {
                allWritten = written("opt_all", all).surfaces.size() == box.surfaces.size();
            } catch (const InputError &) {
                allWritten = false;
            }
            if (f.options.surface)
                QVERIFY2(allWritten == f.options.allSurfaces, f.extension);
            const auto bytes = [&](const char *stem) {
                std::ifstream in(pathFor(stem, f), std::ios::binary);
                return std::string((std::istreambuf_iterator<char>(in)), {});
            };
            exportModel(box, pathFor("opt_again", f), first);
            exportModel(box, pathFor("opt_v22", f), v22);
            // A writer whose output varies from run to run (a zip's time stamps) shows nothing.
            if (bytes("opt_first") == bytes("opt_again"))
                QVERIFY2((bytes("opt_first") != bytes("opt_v22")) == f.options.gmsh, f.extension);
            else
                QVERIFY2(!f.options.gmsh, f.extension);
        }
    }

    // Which rows take which data, and what each loses, follow FormatKeeps.
    void exportFitFollowsTheKeeps()
    {
        for (const FileFormat &f : fileFormats()) {
            if (!f.writes())
                continue;
            QCOMPARE(exportFit(f, ExportData::SurfaceModel) == ExportFit::Fits, !f.needsCells);
            QCOMPARE(exportFit(f, ExportData::TetMesh) == ExportFit::Fits, f.keeps.tetrahedra);
            QCOMPARE(exportFit(f, ExportData::HybridMesh) == ExportFit::Fits,
                     f.keeps.pyramidsPrisms);
            const auto loses = [&](ExportData data, FormatLoss loss) {
                const std::vector<FormatLoss> all = formatLosses(f, data);
                return std::find(all.begin(), all.end(), loss) != all.end();
            };
            QCOMPARE(loses(ExportData::SurfaceModel, FormatLoss::FeatureTypes),
                     !f.keeps.featureTypes);
            QCOMPARE(loses(ExportData::SurfaceModel, FormatLoss::SurfaceNames),
                     !f.keeps.surfaceNames);
            QVERIFY(!loses(ExportData::SurfaceModel, FormatLoss::VolumeCells));
            QCOMPARE(loses(ExportData::TetMesh, FormatLoss::VolumeCells), !f.keeps.tetrahedra);
            QVERIFY(!loses(ExportData::TetMesh, FormatLoss::PyramidsPrisms));
        }
        const FileFormat *so = findFormat("a.so");
        QVERIFY(so && exportFit(*so, ExportData::HybridMesh) == ExportFit::DropsPyramidsPrisms);
        QVERIFY(exportFit(*so, ExportData::SurfaceModel) == ExportFit::NeedsCells);
        QVERIFY(exportFit(*findFormat("a.vtp"), ExportData::TetMesh) == ExportFit::DropsCells);
    }
};

QTEST_APPLESS_MAIN(TestFormats)
#include "test_formats.moc"
