// Writes are atomic: a failed write (exception, file size limit, full disk) leaves no partial file
// and no temporary, an existing file survives, and the error names the file and the cause.
#include "common/error.h"
#include "io/atomic_file.h"
#include "io/gmsh_writer.h"
#include "io/vtk_writer.h"
#include "test_roundtrip_meshes.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace stratamesh;

namespace {

QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
}

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeText(const QString &path, const std::string &text)
{
    writeTextFileAtomically(path.toStdString(), [&](std::ostream &out) { out << text; });
}

std::string failureOf(const std::function<void()> &write)
{
    try {
        write();
    } catch (const FileError &e) {
        return e.what();
    }
    return {};
}

// A mesh of about 2 MB as text: enough to fill a small tmpfs.
VolumeMesh bigMesh()
{
    VolumeMesh m = test::hybridMesh();
    const VolumeMesh base = m;
    for (int copy = 1; copy < 4000; ++copy) {
        const int offset = static_cast<int>(m.points.size());
        for (const Vec3 &p : base.points)
            m.points.push_back(p + Vec3(2.0 * copy, 0.1 / 3.0, 0));
        for (std::size_t c = 0; c < base.cells.size(); ++c) {
            Cell cell = base.cells[c];
            for (int k = 0; k < cell.size(); ++k)
                cell.nodes[k] += offset;
            m.cells.push_back(cell);
            m.cellRegion.push_back(base.cellRegion[c]);
            m.cellQuality.push_back(base.cellQuality[c]);
        }
    }
    return m;
}

} // namespace

class TestAtomicFile : public QObject {
    Q_OBJECT

private slots:
    void writesAndReplaces()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("model.msh");
        writeText(path, "first");
        writeText(path, "second");
        QCOMPARE(contents(path), QByteArray("second"));
        QCOMPARE(entries(dir.path()), QStringList{"model.msh"});
    }

    void newFilesGetTheUsualMode()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("a.txt");
        const mode_t old = ::umask(022);
        writeText(path, "x");
        ::umask(old);
        struct stat st {};
        QCOMPARE(::stat(path.toLocal8Bit().constData(), &st), 0);
        QCOMPARE(int(st.st_mode & 0777), 0644); // not mkstemp's 0600
    }

    void failedWriteKeepsTheOldFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("model.ml");
        writeText(path, "good content");
        bool thrown = false;
        try {
            writeTextFileAtomically(path.toStdString(), [](std::ostream &out) {
                out << std::string(200000, 'x'); // part of it already on disk
                throw InputError("the writer failed half-way");
            });
        } catch (const InputError &) {
            thrown = true;
        }
        QVERIFY(thrown);
        QCOMPARE(contents(path), QByteArray("good content"));
        QCOMPARE(entries(dir.path()), QStringList{"model.ml"});
    }

    void missingFolderIsAClearError()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("no/such/folder/out.vtu");
        const std::string error = failureOf([&] { writeText(path, "x"); });
        QVERIFY2(error.find(path.toStdString()) == 0, error.c_str());
        QVERIFY2(error.find("No such file or directory") != std::string::npos, error.c_str());
    }

    void folderTargetIsAClearError()
    {
        QTemporaryDir dir;
        const std::string error = failureOf([&] { writeText(dir.path(), "x"); });
        QVERIFY2(error.find("is a folder") != std::string::npos, error.c_str());
    }

    void unwritableFolderIsAClearError()
    {
        if (::geteuid() == 0)
            QSKIP(
                "running as root: permissions do not stop writes (the tmpfs test covers failures)");
        QTemporaryDir dir;
        QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        const std::string error = failureOf([&] { writeText(dir.filePath("x.msh"), "x"); });
        QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner
                                              | QFileDevice::ExeOwner);
        QVERIFY2(error.find("Permission denied") != std::string::npos, error.c_str());
    }

    void fileSizeLimitLeavesNothing()
    {
        // RLIMIT_FSIZE makes write() fail like a full disk would (EFBIG), through the same code.
        QTemporaryDir dir;
        const QString path = dir.filePath("big.msh");
        writeText(path, "previous");
        struct rlimit old {};
        QCOMPARE(::getrlimit(RLIMIT_FSIZE, &old), 0);
        const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit small = old;
        small.rlim_cur = 64 * 1024;
        QCOMPARE(::setrlimit(RLIMIT_FSIZE, &small), 0);
        const std::string error = failureOf([&] { writeGmsh(bigMesh(), path.toStdString()); });
        ::setrlimit(RLIMIT_FSIZE, &old);
        std::signal(SIGXFSZ, previousHandler);
        QVERIFY2(error.find("File too large") != std::string::npos, error.c_str());
        QVERIFY2(error.find("nothing was written") != std::string::npos, error.c_str());
        QCOMPARE(contents(path), QByteArray("previous"));
        QCOMPARE(entries(dir.path()), QStringList{"big.msh"});
    }

    void fullDiskLeavesNothing()
    {
        QTemporaryDir dir;
        const QByteArray mountPoint = dir.path().toLocal8Bit();
        if (::geteuid() != 0
            || ::mount("tmpfs", mountPoint.constData(), "tmpfs", 0, "size=256k") != 0)
            QSKIP("*** cannot mount a small tmpfs (needs root): full-disk test SKIPPED; the file "
                  "size "
                  "limit test covers the same code path ***");
        const VolumeMesh mesh = bigMesh();
        const std::string gmsh =
            failureOf([&] { writeGmsh(mesh, dir.filePath("full.msh").toStdString()); });
        const std::string vtk = failureOf([&] {
            writeVtk(mesh, dir.filePath("full.vtk").toStdString(), VtkFileKind::LegacyVtk);
        });
        const std::string text =
            failureOf([&] { writeText(dir.filePath("full.txt"), std::string(1 << 20, 'x')); });
        const QStringList left = entries(dir.path());
        ::umount(mountPoint.constData());
        QVERIFY2(gmsh.find("No space left on device") != std::string::npos, gmsh.c_str());
        QVERIFY2(text.find("No space left on device") != std::string::npos, text.c_str());
        QVERIFY2(!vtk.empty() && vtk.find("full.vtk") != std::string::npos, vtk.c_str());
        QVERIFY2(left.isEmpty(), qPrintable(left.join(", ")));
    }
};

QTEST_GUILESS_MAIN(TestAtomicFile)
#include "test_atomic_file.moc"
