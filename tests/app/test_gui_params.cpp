// Adding a remesh parameter is one table entry: a test entry (RemeshParams' boundary weight α,
// which the product does not expose) appended to a copy of remeshParamTable() appears in the CLI
// usage, help and option parsing, in the report's `parameters` block and back, in the range
// checks, and in the remesh dialog, through the same generators as the product's entries.
#include "command_args.h"
#include "common/error.h"
#include "param_json.h"
#include "params/param_tables.h"
#include "params/param_text.h"
#include "remesh_dialog.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QtTest>

using namespace stratamesh;

namespace {

ParamTable<RemeshParams> tableWithTestEntry()
{
    ParamTable<RemeshParams> table = remeshParamTable();
    ParamInfo i;
    i.key = "boundary_weight", i.flag = "--boundary-weight", i.jsonKey = "boundary_weight";
    i.minimum = 0.0, i.maximum = 1.0, i.valueName = "A", i.decimals = 2, i.thesis = "§4.3.2";
    i.label = "Boundary &weight α:";
    i.help = "Weight of the boundary energy in F = (1 − α) F_CVT + α F_B.";
    table.add(memberParam(&RemeshParams::boundaryWeight, i));
    return table;
}

} // namespace

class TestGuiParams : public QObject {
    Q_OBJECT
private slots:
    void newEntryIsInTheCliHelp()
    {
        const ParamTable<RemeshParams> table = tableWithTestEntry();
        QVERIFY(!remeshParamTable().find("boundary_weight")); // the product's table is unchanged
        const QString usage = QString::fromStdString(paramUsage(table.infos()));
        QVERIFY2(usage.contains(QStringLiteral("[--boundary-weight A]")), qPrintable(usage));
        const QString help = QString::fromStdString(paramHelp(table.infos()));
        QVERIFY2(help.contains(QStringLiteral("  --boundary-weight A\n      Weight of the boundary "
                                              "energy")),
                 qPrintable(help));
        // Its default is RemeshParams' own, its range the entry's.
        QVERIFY2(help.contains(QStringLiteral("Range [0, 1], default 0.2. Thesis §4.3.2.")),
                 qPrintable(help));
        QVERIFY(QString::fromStdString(paramMarkdown(table.infos()))
                    .contains(QStringLiteral("| `--boundary-weight A` |")));

        // The CLI's parser reads it, and refuses a value outside its range with the range.
        RemeshParams p;
        cli::CommandArgs args(QStringLiteral("remesh"),
                              {QStringLiteral("--boundary-weight"), QStringLiteral("0.6")});
        const std::vector<std::string> given = args.params(table, p);
        QCOMPARE(given, std::vector<std::string>{"boundary_weight"});
        QCOMPARE(p.boundaryWeight, 0.6);
        cli::CommandArgs bad(QStringLiteral("remesh"), {QStringLiteral("--boundary-weight=3")});
        try {
            bad.params(table, p);
            QFAIL("3 accepted");
        } catch (const cli::UsageError &e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("in [0, 1], got '3'")),
                     e.what());
        }
    }

    void newEntryIsInTheReportAndItsChecks()
    {
        const ParamTable<RemeshParams> table = tableWithTestEntry();
        RemeshParams p;
        p.boundaryWeight = 0.35;
        const QJsonObject json = paramsToJson(table, p);
        QCOMPARE(json.value(QStringLiteral("boundary_weight")).toDouble(), 0.35);
        QCOMPARE(json.size(), static_cast<qsizetype>(table.params().size()));
        RemeshParams back;
        const QStringList read = paramsFromJson(
            table, QJsonObject{{QStringLiteral("parameters"), json}}, back, QStringLiteral("r"));
        QVERIFY(read.contains(QStringLiteral("boundary_weight")));
        QCOMPARE(back.boundaryWeight, 0.35);
        QJsonObject wrong = json;
        wrong.insert(QStringLiteral("boundary_weight"), 1.5);
        QVERIFY_THROWS_EXCEPTION(FileError,
                                 paramsFromJson(table, wrong, back, QStringLiteral("r")));
        // Core's range check covers it too.
        RemeshParams outside;
        outside.boundaryWeight = -0.1;
        QVERIFY_THROWS_EXCEPTION(InputError, checkParams(table, outside));
        checkParams(remeshParamTable(), outside); // not a product parameter: not checked there
    }

    void newEntryIsInTheDialog()
    {
        const ParamTable<RemeshParams> table = tableWithTestEntry();
        RemeshDialog dialog(1000.0, table);
        auto *field = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("boundary_weight"));
        QVERIFY(field);
        QCOMPARE(field->minimum(), 0.0);
        QCOMPARE(field->maximum(), 1.0);
        QCOMPARE(field->value(), RemeshParams{}.boundaryWeight);
        QVERIFY(field->toolTip().contains(QStringLiteral("boundary energy")));
        QVERIFY(field->toolTip().contains(QStringLiteral("§4.3.2")));
        field->setValue(0.5);
        QCOMPARE(dialog.params().boundaryWeight, 0.5);
        RemeshParams p;
        p.sites = 1200;
        p.boundaryWeight = 0.75;
        dialog.setParams(p);
        QCOMPARE(field->value(), 0.75);
        QCOMPARE(dialog.params().sites, 1200);
        // The product's dialog has every product entry, merge-all included, and not the test one.
        RemeshDialog product(1000.0);
        QVERIFY(!product.findChild<QWidget *>(QStringLiteral("boundary_weight")));
        for (const Param<RemeshParams> &entry : remeshParamTable().params())
            QVERIFY2(product.findChild<QWidget *>(QString::fromStdString(entry.info.key)),
                     entry.info.key.c_str());
        auto *mergeAll = product.findChild<QCheckBox *>(QStringLiteral("merge_all"));
        QVERIFY(mergeAll);
        QVERIFY(!product.params().mergeAllExtraPoints);
        mergeAll->setChecked(true);
        QVERIFY(product.params().mergeAllExtraPoints);
        // Ranges from the table: the fewest sites, the refinement rounds.
        auto *sites = product.findChild<QSpinBox *>(QStringLiteral("sites"));
        QVERIFY(sites);
        QCOMPARE(sites->minimum(), kMinRemeshSites);
        QCOMPARE(sites->maximum(), kMaxRemeshSites);
        auto *rounds = product.findChild<QSpinBox *>(QStringLiteral("refinement_rounds"));
        QVERIFY(rounds);
        QCOMPARE(rounds->value(), RemeshParams{}.refinementRounds);
        QCOMPARE(rounds->maximum(), 100);
    }
};

QTEST_MAIN(TestGuiParams)
#include "test_gui_params.moc"
