// Hostile Gmsh files (issue 18): every count is checked against what the rest of the file can hold
// before anything is sized by it, and against the data it announces; each a FileError with line.
#include "bounded_read.h"
#include "common/error.h"
#include "io/model_reader.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::testing;

namespace {

const QByteArray msh41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
const QByteArray msh22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";

} // namespace

class TestMalformedGmsh : public QObject {
    Q_OBJECT

private slots:
    void countsBeyondTheFile_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        // Before: "out of memory" with no file or line.
        QTest::newRow("4.1 block of 2e9 nodes")
            << msh41 + "$Nodes\n1 2000000000 1 2000000000\n2 1 0 2000000000\n1\n0 0 0\n$EndNodes\n"
            << 5 << "the number of nodes is 2000000000, more than the remaining";
        QTest::newRow("4.1 block count") << msh41 + "$Nodes\n2000000000 3 1 3\n"
                                         << 5 << "the number of node blocks is 2000000000";
        QTest::newRow("4.1 nodes in block")
            << msh41
                   + "$Nodes\n1 3 1 3\n2 1 0 2000000000\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
            << 6 << "the number of nodes in the block is 2000000000";
        QTest::newRow("2.2 nodes") << msh22 + "$Nodes\n2000000000\n1 0 0 0\n$EndNodes\n"
                                   << 5 << "the number of nodes is 2000000000";
        QTest::newRow("2.2 elements")
            << msh22 + "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1999999999\n"
            << 9 << "the number of elements is 1999999999";
        QTest::newRow("physical names") << msh22 + "$PhysicalNames\n2000000000\n"
                                        << 5 << "the number of physical names is 2000000000";
        QTest::newRow("4.1 entities") << msh41 + "$Entities\n0 0 2000000000 0\n"
                                      << 5 << "an entity count is 2000000000";
        QTest::newRow("negative nodes") << msh22 + "$Nodes\n-5\n$EndNodes\n"
                                        << 5 << "the number of nodes is negative (-5)";
        QTest::newRow("negative elements") << msh41 + "$Elements\n-1 0 1 1\n$EndElements\n"
                                           << 5 << "the number of element blocks is negative";
    }
    void countsBeyondTheFile()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), "hostile.msh", text);
        const BoundedRead r = runBounded([&] { readModel(path); });
        qInfo("%s in %.3f s, +%ld KiB: %s", outcomeName(r.outcome), r.seconds, r.peakKiB,
              r.message.c_str());
        QCOMPARE(outcomeName(r.outcome), outcomeName(BoundedRead::FileErrorRaised));
        const QString prefix = QString::fromStdString(path) + ":" + QString::number(line) + ": ";
        QVERIFY2(QString::fromStdString(r.message).startsWith(prefix + cause), r.message.c_str());
        QVERIFY(r.peakKiB < 200 * 1024);
    }

    void countsDisagreeingWithTheData_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("cause");
        QTest::newRow("4.1 nodes header")
            << msh41 + "$Nodes\n1 4 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
            << 5 << "the $Nodes header declares 4 nodes, its blocks hold 3";
        QTest::newRow("4.1 elements header")
            << msh41
                   + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 "
                     "0\n$EndNodes\n$Elements\n1 2 1 1\n2 1 "
                     "2 1\n1 1 2 3\n$EndElements\n"
            << 15 << "the $Elements header declares 2 elements, its blocks hold 1";
        QTest::newRow("2.2 more nodes than declared")
            << msh22 + "$Nodes\n1\n1 0 0 0\n2 1 0 0\n$EndNodes\n"
            << 7 << "expected $EndNodes";
        QTest::newRow("2.2 truncated elements")
            << msh22
                   + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n2\n1 2 2 1 1 1 2 "
                     "3\n"
            << 13 << "unexpected end of file";
        QTest::newRow("element node out of range")
            << msh22
                   + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 2 1 1 1 2 "
                     "9\n$EndElements\n"
            << 12 << "element uses node 9, which is not in $Nodes";
        QTest::newRow("negative tag count")
            << msh22
                   + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 -4 1 2 "
                     "3\n$EndElements\n"
            << 12 << "element line too short for its tags";
    }
    void countsDisagreeingWithTheData()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, cause);
        QTemporaryDir dir;
        const std::string path = writeTestFile(dir.path(), "hostile.msh", text);
        try {
            readModel(path);
            QFAIL("read a file whose counts disagree with its data");
        } catch (const FileError &e) {
            QCOMPARE(e.line(), line);
            QVERIFY2(QString::fromStdString(e.cause()).contains(cause), e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestMalformedGmsh)
#include "test_malformed_gmsh.moc"
