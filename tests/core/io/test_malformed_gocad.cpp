// Hostile Gocad files (issue 18): a brace block never closed must not swallow the END of its
// object or the next object (before: one surface named after the first, holding the second's
// triangles); each is a FileError naming the block's line and where it ran into END or GOCAD.
#include "common/error.h"
#include "io/model_reader.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

QByteArray tsurf(const QByteArray &name, const QByteArray &extra = {})
{
    return "GOCAD TSurf 1\nHEADER {\nname: " + name + "\n}\n" + extra
           + "VRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n";
}

} // namespace

class TestMalformedGocad : public QObject {
    Q_OBJECT

private slots:
    void openBlocksAreFileErrors_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        QTest::newRow("property class header, then a second TSurf")
            << "two.ts"
            << tsurf("first", "PROPERTY_CLASS_HEADER Z {\nlow_clip: 0\n") + tsurf("second") << 11
            << "the { } block started at line 5 is not closed by '}' before END";
        QTest::newRow("header never closed")
            << "header.ts"
            << QByteArray(
                   "GOCAD TSurf 1\nHEADER {\nname: a\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\n"
                   "TRGL 1 2 3\nEND\n")
            << 8 << "the HEADER block started at line 2 is not closed by '}' before END";
        QTest::newRow("header without its brace")
            << "nobrace.ts" << QByteArray("GOCAD TSurf 1\nHEADER\nEND\n") << 3
            << "the HEADER block started at line 2 is not closed by '}' before END";
        QTest::newRow("block into the next object")
            << "next.ts" << QByteArray("GOCAD TSurf 1\nPROPERTY_CLASS_HEADER Z {\n") + tsurf("b")
            << 3 << "is not closed by '}' before GOCAD";
        QTest::newRow("tsolid header")
            << "header.so"
            << QByteArray(
                   "GOCAD TSolid 1\nHEADER {\nname: a\nTVOLUME a\nVRTX 1 0 0 0\nVRTX 2 1 0 0\n"
                   "VRTX 3 0 1 0\nVRTX 4 0 0 1\nTETRA 1 2 3 4\nEND\n")
            << 10 << "HEADER block started at line 2 is not closed by '}' before END";
        QTest::newRow("tsolid block")
            << "block.so"
            << QByteArray("GOCAD TSolid 1\nPROPERTY_CLASS_HEADER Z {\nTVOLUME a\nVRTX 1 0 0 "
                          "0\nVRTX 2 1 0 0\n"
                          "VRTX 3 0 1 0\nVRTX 4 0 0 1\nTETRA 1 2 3 4\nEND\n")
            << 9 << "{ } block started at line 2 is not closed by '}' before END";
    }
    void openBlocksAreFileErrors()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const QString path = QDir(dir.path()).filePath(name);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
        f.close();
        try {
            const Model m = readModel(path.toStdString());
            QFAIL(qPrintable("read as " + QString::number(m.surfaces.size()) + " surface(s)"));
        } catch (const FileError &e) {
            QCOMPARE(e.line(), line);
            QVERIFY2(QString::fromStdString(e.cause()).contains(cause), e.what());
        }
    }

    // A block closed on a later line is still skipped as before.
    void closedBlocksAreSkipped()
    {
        QTemporaryDir dir;
        const QString path = QDir(dir.path()).filePath("closed.ts");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(tsurf("first", "PROPERTY_CLASS_HEADER Z {\nlow_clip: 0\n}\n") + tsurf("second"));
        f.close();
        const Model m = readModel(path.toStdString());
        QCOMPARE(int(m.surfaces.size()), 2);
    }
};

QTEST_GUILESS_MAIN(TestMalformedGocad)
#include "test_malformed_gocad.moc"
