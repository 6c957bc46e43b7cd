// Mixed meshes leave StrataMesh with every cell positive for independent readers: VTK's own
// vtkCellSizeFilter (signed, in VTK's node order) on the .vtu, meshio on both files with the
// documented node orders, and Gmsh's Jacobian check (AnalyseMeshQuality) on the .msh. An inverted
// cell written on purpose is seen inverted by the same readers, so the checks can fail.
#include "../io/test_roundtrip_meshes.h"
#include "io/gmsh_writer.h"
#include "io/mesh_writer.h"
#include "mixed_fixture.h"

#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

// Prints one signed volume per volume cell of the file in meshio's node order, which is Gmsh's for
// both files (meshio permutes VTK wedges, whose base triangle faces away from the top).
const char *meshioVolumes = R"(
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1]); p = m.points
def tet(a, b, c, d): return np.dot(p[b] - p[a], np.cross(p[c] - p[a], p[d] - p[a])) / 6
for block in m.cells:
    for n in block.data:
        if block.type == 'tetra': v = [tet(*n)]
        elif block.type == 'pyramid': v = [tet(n[0], n[1], n[2], n[4]), tet(n[0], n[2], n[3], n[4])]
        elif block.type == 'wedge':
            v = [tet(n[0], n[1], n[2], n[3]), tet(n[1], n[2], n[3], n[4]), tet(n[2], n[3], n[4], n[5])]
        else: continue
        print(block.type, min(v), sum(v))
)";

const char *vtkVolumes = R"(
import sys, vtk
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
f = vtk.vtkCellSizeFilter(); f.SetInputData(r.GetOutput()); f.Update()
g = f.GetOutput(); a = g.GetCellData().GetArray('Volume')
for i in range(g.GetNumberOfCells()):
    if g.GetCell(i).GetCellDimension() == 3: print(g.GetCellType(i), a.GetValue(i))
)";

QStringList runPython(const QString &python, const char *script, const QString &file)
{
    QProcess p;
    p.start(python, {"-c", script, file});
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
        qWarning("%s", p.readAllStandardError().constData());
        return {};
    }
    return QString(p.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
}

// Smallest volume in a "type min sum" / "type volume" listing.
double smallest(const QStringList &lines, int column)
{
    double m = 1e300;
    for (const QString &l : lines)
        m = std::min(m, l.split(' ').at(column).toDouble());
    return m;
}

VolumeMesh invertedCopy()
{
    VolumeMesh m = test::mixedFixture();
    std::swap(m.cells[0].nodes[1], m.cells[0].nodes[2]); // the prism, bottom and top reversed
    std::swap(m.cells[0].nodes[4], m.cells[0].nodes[5]);
    return m;
}

} // namespace

class TestMixedMeshExport : public QObject {
    Q_OBJECT

private slots:
    void vtuVolumesArePositiveForVtkAndMeshio()
    {
        const QString python = test::pythonWithMeshio();
        if (python.isEmpty())
            QSKIP("*** python3-meshio is not installed: independent reader check SKIPPED ***");
        QTemporaryDir dir;
        const QString good = dir.filePath("good.vtu"), bad = dir.filePath("bad.vtu");
        exportVolumeMesh(test::mixedFixture(), good.toStdString());
        exportVolumeMesh(invertedCopy(), bad.toStdString());

        const QStringList vtkGood = runPython(python, vtkVolumes, good);
        QCOMPARE(vtkGood.size(), 5);
        QVERIFY(smallest(vtkGood, 1) > 0.1);
        double total = 0.0;
        for (const QString &l : vtkGood)
            total += l.split(' ').at(1).toDouble();
        QVERIFY(std::abs(total - test::fixtureCoreVolume() - test::fixtureCapVolume()) < 1e-9);
        QVERIFY(smallest(runPython(python, vtkVolumes, bad), 1) < 0.0);

        const QStringList meshioGood = runPython(python, meshioVolumes, good);
        QCOMPARE(meshioGood.size(), 5);
        QVERIFY2(smallest(meshioGood, 1) > 0.01, qPrintable(meshioGood.join(';')));
        QVERIFY(smallest(runPython(python, meshioVolumes, bad), 1) < 0.0);
    }

    void mshVolumesArePositiveForMeshioAndGmsh()
    {
        QTemporaryDir dir;
        const QString good = dir.filePath("good.msh"), bad = dir.filePath("bad.msh");
        writeGmsh(test::mixedFixture(), good.toStdString());
        writeGmsh(invertedCopy(), bad.toStdString());

        const QString python = test::pythonWithMeshio();
        if (!python.isEmpty()) {
            const QStringList lines = runPython(python, meshioVolumes, good);
            QCOMPARE(lines.size(), 5);
            QVERIFY(smallest(lines, 1) > 0.01);
            QVERIFY(smallest(runPython(python, meshioVolumes, bad), 1) < 0.0);
        }

        const QString gmsh = QStandardPaths::findExecutable("gmsh");
        if (gmsh.isEmpty())
            QSKIP("*** gmsh is not installed: Jacobian check SKIPPED ***");
        // Gmsh's smallest Jacobian determinant over the 3D elements ("minJ = min, avg, max").
        auto minJacobian = [&](const QString &msh) {
            const QString geo = msh + ".geo";
            QFile f(geo);
            f.open(QIODevice::WriteOnly);
            f.write(QStringLiteral("Merge \"%1\";\n"
                                   "Plugin(AnalyseMeshQuality).JacobianDeterminant = 1;\n"
                                   "Plugin(AnalyseMeshQuality).DimensionOfElements = 3;\n"
                                   "Plugin(AnalyseMeshQuality).Run;\n")
                        .arg(msh)
                        .toUtf8());
            f.close();
            QProcess p;
            p.start(gmsh, {"-nopopup", geo, "-0", "-o", msh + ".out.msh"});
            p.waitForFinished(120000);
            const QString out = p.readAllStandardOutput() + p.readAllStandardError();
            const QRegularExpression re(QStringLiteral("minJ\\s*=\\s*([-+0-9.eE]+),"));
            const QRegularExpressionMatch m = re.match(out);
            return m.hasMatch() ? m.captured(1).toDouble() : std::nan("");
        };
        const double goodJ = minJacobian(good);
        QVERIFY2(goodJ > 0.0, qPrintable(QString::number(goodJ)));
        QVERIFY(minJacobian(bad) < 0.0);
    }
};

QTEST_GUILESS_MAIN(TestMixedMeshExport)
#include "test_mixed_mesh_export.moc"
