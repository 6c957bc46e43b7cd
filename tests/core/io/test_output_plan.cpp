// OutputPlan (core/io/output_plan.h): outputs checked before the work, written all or none.
#include "common/error.h"
#include "io/output_plan.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace stratamesh;

namespace {

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
}

// Files of dir, hidden ones (temporaries) included.
QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

std::string text(const QString &path)
{
    return path.toStdString();
}

} // namespace

class TestOutputPlan : public QObject {
    Q_OBJECT

private slots:
    void writesEveryOutputOnCommit()
    {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.ml"), b = dir.filePath("b.json");
        OutputPlan plan;
        plan.add(text(a), "model");
        plan.add(text(b), "report");
        // Planned, not yet written: only the two hidden temporaries exist.
        QCOMPARE(entries(dir.path()).size(), 2);
        QVERIFY(!QFile::exists(a) && !QFile::exists(b));
        plan.writeText(text(a), [](std::ostream &o) { o << "model"; });
        plan.write(text(b), [](const std::string &temporary) {
            QVERIFY(QString::fromStdString(temporary).endsWith(".json")); // extension kept
            std::ofstream(temporary) << "report";
        });
        QVERIFY(!QFile::exists(a));
        plan.commit();
        QCOMPARE(readAll(a), QByteArray("model"));
        QCOMPARE(readAll(b), QByteArray("report"));
        QCOMPARE(entries(dir.path()), QStringList({"a.ml", "b.json"}));
    }

    void failureLeavesNoOutput()
    {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.ml"), b = dir.filePath("b.json");
        writeBytes(b, "old report");
        {
            OutputPlan plan;
            plan.add(text(a), "model");
            plan.add(text(b), "report");
            plan.writeText(text(a), [](std::ostream &o) { o << "model"; });
            QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                                     plan.write(text(b), [](const std::string &) {
                                         throw std::runtime_error("writer failed");
                                     }));
        } // the plan is dropped without commit
        QVERIFY(!QFile::exists(a));
        QCOMPARE(readAll(b), QByteArray("old report"));
        QCOMPARE(entries(dir.path()), QStringList({"b.json"}));
    }

    void commitOfAnUnwrittenOutputWritesNothing()
    {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.ml"), b = dir.filePath("b.json");
        {
            OutputPlan plan;
            plan.add(text(a), "model");
            plan.add(text(b), "report");
            plan.writeText(text(a), [](std::ostream &o) { o << "model"; });
            QVERIFY_THROWS_EXCEPTION(FileError, plan.commit());
        }
        QVERIFY(entries(dir.path()).isEmpty());
    }

    void failedRenameUndoesTheOthers()
    {
        // The second target becomes a folder between the plan and the commit: its rename fails,
        // the first output (new) is removed and the third (replaced) keeps its old content.
        QTemporaryDir dir;
        const QString a = dir.filePath("a.ml"), b = dir.filePath("b.json"),
                      c = dir.filePath("c.txt");
        writeBytes(a, "old model");
        {
            OutputPlan plan;
            plan.add(text(a), "model");
            plan.add(text(b), "report");
            plan.add(text(c), "sites");
            for (const QString &p : {a, b, c})
                plan.writeText(text(p), [](std::ostream &o) { o << "new"; });
            QVERIFY(QDir(dir.path()).mkdir("b.json"));
            QVERIFY(QFile::exists(dir.filePath("b.json/")));
            QFile(dir.filePath("b.json/keep")).open(QIODevice::WriteOnly);
            QVERIFY_THROWS_EXCEPTION(FileError, plan.commit());
        }
        QCOMPARE(readAll(a), QByteArray("old model"));
        QVERIFY(!QFile::exists(c));
        QCOMPARE(entries(dir.path()), QStringList({"a.ml"}));
    }

    void refusesBeforeAnyWork_data()
    {
        QTest::addColumn<QString>("target");
        QTest::addColumn<QString>("cause");
        QTest::newRow("missing folder") << "missing/out.ml"
                                        << "does not exist";
        QTest::newRow("folder is a file") << "in.ml/out.ml"
                                          << "is not a folder";
        QTest::newRow("a folder") << "sub"
                                  << "it is a folder";
        QTest::newRow("the input") << "in.ml"
                                   << "would replace the input file";
        QTest::newRow("the input by another name") << "sub/../in.ml"
                                                   << "would replace the input";
        QTest::newRow("no name") << ""
                                 << "no file name";
    }
    void refusesBeforeAnyWork()
    {
        QFETCH(QString, target);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("sub"));
        writeBytes(dir.filePath("in.ml"), "input");
        OutputPlan plan({text(dir.filePath("in.ml"))});
        const std::string path = target.isEmpty() ? std::string() : text(dir.filePath(target));
        try {
            plan.add(path, "model");
            QFAIL("accepted");
        } catch (const FileError &e) {
            QVERIFY2(QString(e.what()).contains(cause), e.what());
            QCOMPARE(e.file(), path);
        }
        QCOMPARE(entries(dir.path()), QStringList({"in.ml"}));
        QCOMPARE(readAll(dir.filePath("in.ml")), QByteArray("input"));
    }

    void overwriteReplacesTheInput()
    {
        QTemporaryDir dir;
        const QString in = dir.filePath("in.ml");
        writeBytes(in, "input");
        OutputPlan plan({text(in)}, true);
        plan.add(text(in), "model");
        plan.writeText(text(in), [](std::ostream &o) { o << "output"; });
        plan.commit();
        QCOMPARE(readAll(in), QByteArray("output"));
        QCOMPARE(entries(dir.path()), QStringList({"in.ml"}));
    }

    void sameOutputTwiceRefused()
    {
        QTemporaryDir dir;
        OutputPlan plan;
        plan.add(text(dir.filePath("a.json")), "model");
        QVERIFY_THROWS_EXCEPTION(FileError, plan.add(text(dir.filePath("./a.json")), "report"));
    }

    void discardedOutputLeftAlone()
    {
        QTemporaryDir dir;
        const QString mesh = dir.filePath("m.vtu"), report = dir.filePath("r.json");
        writeBytes(mesh, "old mesh");
        OutputPlan plan;
        plan.add(text(mesh), "mesh");
        plan.add(text(report), "report");
        plan.discard(text(mesh));
        plan.writeText(text(report), [](std::ostream &o) { o << "failed run"; });
        plan.commit();
        QCOMPARE(readAll(mesh), QByteArray("old mesh"));
        QCOMPARE(readAll(report), QByteArray("failed run"));
        QCOMPARE(entries(dir.path()), QStringList({"m.vtu", "r.json"}));
    }
};

QTEST_GUILESS_MAIN(TestOutputPlan)
#include "test_output_plan.moc"
