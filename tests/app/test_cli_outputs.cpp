// Every output of every command (issue 18), as a user or a script meets it: an output that cannot
// be written is refused before any work, with nothing left behind; an output naming the input is
// refused unless --overwrite, and then replaces it. "Before any work" is shown by giving a
// malformed input: the refusal must name the output, never the input's defect, so the input was
// not even read.
#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/stat.h>

using stratamesh::test::CliRun;
using stratamesh::test::runCli;

namespace {

// Not a Gocad file: reading it fails at line 1.
const QByteArray malformed = "this is not a model\n";

void writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Every file under dir, hidden ones (temporaries) included, relative to it.
QStringList filesUnder(const QString &dir)
{
    QStringList files;
    QDir d(dir);
    for (const QFileInfo &info :
         d.entryInfoList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name)) {
        if (info.isDir()) {
            for (const QString &f : filesUnder(info.filePath()))
                files << info.fileName() + QLatin1Char('/') + f;
        } else {
            files << info.fileName();
        }
    }
    return files;
}

ino_t inode(const QString &path)
{
    struct stat st {};
    return ::stat(path.toLocal8Bit().constData(), &st) == 0 ? st.st_ino : 0;
}

// A small valid model made by the tool itself: a layered box.
QString layeredModel(const QString &dir, const QString &name)
{
    const QString path = QDir(dir).filePath(name);
    const CliRun r = runCli({"synthetic", "layered", "--horizons", "1", "-o", path});
    if (r.exitCode != 0)
        qWarning("%s", qPrintable(r.err));
    return path;
}

} // namespace

class TestCliOutputs : public QObject {
    Q_OBJECT

private slots:
    // One run per command and output, each into a folder that does not exist.
    void unwritableOutputRefusedBeforeWork_data()
    {
        QTest::addColumn<QStringList>("arguments"); // IN is the malformed input, OUT the output
        QTest::addColumn<QString>("output");
        QTest::newRow("remesh model")
            << QStringList{"remesh", "IN", "--sites", "100", "-o", "OUT"} << "missing/out.ml";
        QTest::newRow("remesh report")
            << QStringList{"remesh", "IN", "--sites", "100", "-o", "ok.ml", "--report", "OUT"}
            << "missing/report.json";
        QTest::newRow("convert") << QStringList{"convert", "IN", "OUT"} << "missing/out.vtu";
        QTest::newRow("cvt sites")
            << QStringList{"cvt", "IN", "--sites", "10", "--sites-out", "OUT"} << "missing/s.xyz";
        QTest::newRow("complexity cells")
            << QStringList{"complexity", "IN", "--cells", "10,20", "--cells-vtk", "OUT"}
            << "missing/cells.vtu";
        QTest::newRow("tetmesh mesh")
            << QStringList{"tetmesh", "IN", "-o", "OUT"} << "missing/t.vtu";
        QTest::newRow("tetmesh report")
            << QStringList{"tetmesh", "IN", "-o", "ok.vtu", "--report", "OUT"} << "missing/r.json";
        QTest::newRow("tetmesh poly")
            << QStringList{"tetmesh", "IN", "--report", "ok.json", "--poly", "OUT"}
            << "missing/p.poly";
        QTest::newRow("synthetic")
            << QStringList{"synthetic", "layered", "-o", "OUT"} << "missing/s.ml";
        // A path below a plain file: refused even for root, who may write anywhere else.
        QTest::newRow("remesh report below a file")
            << QStringList{"remesh", "IN", "--sites", "100", "-o", "ok.ml", "--report", "OUT"}
            << "bad.ml/report.json";
    }
    void unwritableOutputRefusedBeforeWork()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, output);
        QTemporaryDir dir;
        const QString in = dir.filePath("bad.ml");
        writeFile(in, malformed);
        const QString out = dir.filePath(output);
        for (QString &a : arguments) {
            if (a == QLatin1String("IN"))
                a = in;
            else if (a == QLatin1String("OUT"))
                a = out;
            else if (a.contains(QLatin1Char('.')))
                a = dir.filePath(a); // the other outputs, writable
        }
        const CliRun r = runCli(arguments);
        QVERIFY(r.finished);
        QVERIFY2(r.exitCode != 0, qPrintable(r.out));
        // complexity names its files OUT_<cells>.vtu: the folder is what must be named.
        QVERIFY2(r.err.contains(QFileInfo(out).path()), qPrintable(r.err));
        QVERIFY2(!r.err.contains(QStringLiteral("bad.ml:1")), qPrintable(r.err)); // input unread
        QCOMPARE(filesUnder(dir.path()), QStringList{"bad.ml"});
        QCOMPARE(readAll(in), malformed);
    }

    // Each command whose output may name its input: refused, then accepted with --overwrite.
    void outputEqualToInput_data()
    {
        QTest::addColumn<QString>("input");         // made from the layered box by convert
        QTest::addColumn<QStringList>("arguments"); // IN both the input and an output
        QTest::newRow("remesh") << "in.ml" << QStringList{"remesh",       "IN", "--sites", "300",
                                                          "--iterations", "5",  "-o",      "IN"};
        QTest::newRow("remesh report")
            << "in.ml" << QStringList{"remesh", "IN", "--sites", "300",      "--iterations",
                                      "5",      "-o", "out.ml",  "--report", "IN"};
        QTest::newRow("convert") << "in.ml" << QStringList{"convert", "IN", "IN"};
        QTest::newRow("convert vtu") << "in.vtu" << QStringList{"convert", "IN", "IN"};
        QTest::newRow("cvt") << "in.ml" << QStringList{"cvt",          "IN", "--sites",     "20",
                                                       "--iterations", "2",  "--sites-out", "IN"};
        QTest::newRow("complexity")
            << "in.vtu" << QStringList{"complexity",   "IN", "--cells",     "20",
                                       "--iterations", "2",  "--cells-vtk", "IN"};
        QTest::newRow("tetmesh report")
            << "in.ml" << QStringList{"tetmesh", "IN", "--report", "IN"};
        QTest::newRow("tetmesh mesh") << "in.vtu" << QStringList{"tetmesh", "IN", "-o", "IN"};
    }
    void outputEqualToInput()
    {
        QFETCH(QString, input);
        QFETCH(QStringList, arguments);
        QTemporaryDir dir;
        const QString model = layeredModel(dir.path(), "layered.ml");
        const QString in = dir.filePath(input);
        const CliRun c = runCli({"convert", model, in});
        QVERIFY2(c.exitCode == 0, qPrintable(c.err));
        const QByteArray before = readAll(in);
        const ino_t inodeBefore = inode(in);
        QVERIFY(!before.isEmpty());
        for (QString &a : arguments) {
            if (a == QLatin1String("IN"))
                a = in;
            else if (a.contains(QLatin1Char('.')))
                a = dir.filePath(a);
        }
        const QStringList filesBefore = filesUnder(dir.path());

        const CliRun refused = runCli(arguments);
        QVERIFY(refused.finished);
        QVERIFY2(refused.exitCode != 0, qPrintable(refused.out));
        QVERIFY2(refused.err.contains(QStringLiteral("would replace the input file")),
                 qPrintable(refused.err));
        QVERIFY2(refused.err.contains(QStringLiteral("--overwrite")), qPrintable(refused.err));
        QCOMPARE(readAll(in), before);
        QCOMPARE(filesUnder(dir.path()), filesBefore);

        const CliRun accepted = runCli(arguments + QStringList{"--overwrite"});
        QVERIFY(accepted.finished);
        QVERIFY2(accepted.exitCode == 0, qPrintable(accepted.err));
        const QByteArray after = readAll(in);
        QVERIFY(!after.isEmpty());
        // Replaced by a rename (a new file), even where the bytes come out the same (convert).
        QVERIFY(inode(in) != inodeBefore);
        // No temporary left: only the input (now replaced) and the other outputs named.
        for (const QString &f : filesUnder(dir.path()))
            QVERIFY2(!f.startsWith(QLatin1Char('.')), qPrintable(f));
    }

    // A run that fails after the work (remesh refusing an invalid result) leaves no output,
    // not even the report, and an existing output as it was.
    void failedRunLeavesNoOutput()
    {
        QTemporaryDir dir;
        const QString model = layeredModel(dir.path(), "layered.ml");
        const QString out = dir.filePath("out.ml"), report = dir.filePath("report.json");
        writeFile(report, "previous report\n");
        // 4 sites for 6+ surfaces: refused (by the parameter check or as an invalid result).
        const CliRun r = runCli(
            {"remesh", model, "--sites", "4", "--iterations", "2", "-o", out, "--report", report});
        QVERIFY(r.finished);
        QVERIFY(r.exitCode != 0);
        QVERIFY(!QFile::exists(out));
        QCOMPARE(readAll(report), QByteArray("previous report\n"));
        QCOMPARE(filesUnder(dir.path()), (QStringList{"layered.ml", "report.json"}));
    }

    // Two outputs of one run naming the same file: refused before the work.
    void sameOutputTwiceRefused()
    {
        QTemporaryDir dir;
        const QString in = dir.filePath("bad.ml");
        writeFile(in, malformed);
        const QString out = dir.filePath("out.ml");
        const CliRun r = runCli({"remesh", in, "--sites", "100", "-o", out, "--report", out});
        QVERIFY(r.finished);
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(QStringLiteral("named twice")), qPrintable(r.err));
        QCOMPARE(filesUnder(dir.path()), QStringList{"bad.ml"});
    }
};

QTEST_GUILESS_MAIN(TestCliOutputs)
#include "test_cli_outputs.moc"
