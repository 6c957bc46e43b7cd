// The parameter tables: every entry is well formed (unique keys, flags and JSON keys, a default
// inside its range), ranges are checked with InputError naming the range, and the texts made
// from a table hold every entry.
#include "common/error.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "params/param_tables.h"
#include "params/param_text.h"

#include <QtTest>

#include <set>

using namespace stratamesh;

namespace {

template <class P>
void checkWellFormed(const ParamTable<P> &table)
{
    std::set<std::string> keys, flags, json;
    for (const Param<P> &p : table.params()) {
        const ParamInfo &i = p.info;
        QVERIFY2(keys.insert(i.key).second, i.key.c_str());
        QVERIFY2(flags.insert(i.flag).second, i.flag.c_str());
        QVERIFY2(json.insert(i.jsonKey).second, i.jsonKey.c_str());
        QVERIFY2(i.flag.rfind("--", 0) == 0, i.flag.c_str());
        QVERIFY2(!i.label.empty() && !i.help.empty(), i.key.c_str());
        if (i.type == ParamType::Flag)
            continue;
        QVERIFY2(i.minimum <= i.maximum, i.key.c_str());
        QVERIFY2(!i.valueName.empty(), i.key.c_str());
        if (i.type == ParamType::IntList) {
            QVERIFY(!i.defaultList.empty());
            for (double v : i.defaultList)
                QVERIFY2(paramValueError(i, v).empty(), i.key.c_str());
        } else {
            QVERIFY2(paramValueError(i, i.defaultValue).empty(), i.key.c_str());
        }
    }
    checkParams(table, P{}); // the struct's defaults pass its own checks
}

} // namespace

class TestParamTable : public QObject {
    Q_OBJECT
private slots:
    void tablesAreWellFormed()
    {
        checkWellFormed(remeshParamTable());
        checkWellFormed(complexityParamTable());
        checkWellFormed(tetgenParamTable());
        checkWellFormed(cvtParamTable());
        QCOMPARE(remeshParamTable().info("sites").minimum, double(kMinRemeshSites));
        QCOMPARE(remeshParamTable().info("sites").maximum, double(kMaxRemeshSites));
        QCOMPARE(remeshParamTable().info("iterations").defaultValue, 100.0);
    }

    void numbersReadBack()
    {
        QCOMPARE(formatParamNumber(10000000), std::string("10000000"));
        QCOMPARE(formatParamNumber(0.4), std::string("0.4"));
        QCOMPARE(formatParamNumber(1.414), std::string("1.414"));
        QCOMPARE(formatParamNumber(1e300), std::string("1e+300"));
        QCOMPARE(formatParamNumber(0.001), std::string("0.001"));
    }

    void valuesOutsideTheRangeAreRefused()
    {
        const ParamInfo &sites = remeshParamTable().info("sites");
        QVERIFY(paramValueError(sites, 0).empty()); // 0: from the edge length
        QVERIFY(paramValueError(sites, 4).empty());
        QCOMPARE(paramValueError(sites, 3), std::string("is 3, outside [4, 10000000] or 0"));
        QVERIFY(!paramValueError(sites, 4.5).empty()); // whole numbers only
        QVERIFY(!paramValueError(sites, 1e7 + 1).empty());
        const ParamInfo &strip = remeshParamTable().info("strip_factor");
        QVERIFY(paramValueError(strip, 0.0).empty());
        QVERIFY(!paramValueError(strip, std::nan("")).empty());
        QCOMPARE(paramValueError(strip, 1.5), std::string("is 1.5, outside [0, 1] × edge length"));

        RemeshParams remesh;
        remesh.sites = 100;
        remesh.stripWidthFactor = 2.0;
        try {
            checkParams(remeshParamTable(), remesh);
            QFAIL("strip factor 2 accepted");
        } catch (const InputError &e) {
            QCOMPARE(std::string(e.what()),
                     std::string("remesh: strip_factor is 2, outside [0, 1] × edge length "
                                 "(--strip-factor)"));
        }
        // remeshModel enforces them, before any work.
        const Model box = recoverTopology(layeredBox(LayeredBoxParams{}));
        QVERIFY_THROWS_EXCEPTION(InputError, remeshModel(box, remesh));
        remesh.stripWidthFactor = 0.4;
        remesh.iterations = -1;
        QVERIFY_THROWS_EXCEPTION(InputError, remeshModel(box, remesh));

        ComplexityParams complexity;
        complexity.geometric.h = 1e-6; // the CLI took it, the dialog did not: now neither
        QVERIFY_THROWS_EXCEPTION(InputError, checkParams(complexityParamTable(), complexity));
        complexity.geometric.h = 100;
        complexity.cells = {100, 0};
        QVERIFY_THROWS_EXCEPTION(InputError, checkParams(complexityParamTable(), complexity));
        QVERIFY_THROWS_EXCEPTION(InputError, computeComplexity(box, complexity));

        TetgenParams tetgen;
        tetgen.timeLimitSeconds = 2e9;
        QVERIFY_THROWS_EXCEPTION(InputError, checkParams(tetgenParamTable(), tetgen));
        CvtParams cvt;
        cvt.alpha = 1.5;
        QVERIFY_THROWS_EXCEPTION(InputError, checkParams(cvtParamTable(), cvt));
    }

    void textsHoldEveryEntry()
    {
        const std::vector<ParamInfo> infos = remeshParamTable().infos();
        const std::string usage = paramUsage(infos, "(--sites N | --edge-length L) ");
        QVERIFY(usage.find("--sites") == std::string::npos); // named by the command line itself
        QVERIFY(usage.find("[--d-resolution D]") != std::string::npos);
        const std::string help = paramHelp(infos);
        const std::string markdown = paramMarkdown(infos);
        for (const ParamInfo &i : infos) {
            QVERIFY2(help.find("  " + i.flag) != std::string::npos, i.flag.c_str());
            QVERIFY2(markdown.find("`" + i.flag) != std::string::npos, i.flag.c_str());
            if (i.key != "sites" && i.key != "edge_length")
                QVERIFY2(usage.find("[" + i.flag) != std::string::npos, i.flag.c_str());
        }
        QVERIFY(help.find("Range [0, 1] × edge length, default 0.4.") != std::string::npos);
        QVERIFY(paramHelp(complexityParamTable().infos()).find("default 100,1000,10000")
                != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(TestParamTable)
#include "test_param_table.moc"
