// The French translation is complete, current with the sources, and loaded at run time.
#include "core_text.h"
#include "gui_options.h"
#include "ledger_table_model.h"
#include "main_window.h"
#include "model/validity.h"
#include "translations.h"
#include "validity_messages.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QMenuBar>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

using namespace stratamesh;

namespace {

struct TsMessage {
    QString context, source, translation;
    bool finished = true;
    bool numerus = false;
    int numerusForms = 0;
};

QList<TsMessage> readTs(const QString &path)
{
    QList<TsMessage> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return messages;
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("name"))
            context = xml.readElementText();
        else if (xml.name() == QLatin1String("message")) {
            current =
                TsMessage{context,
                          {},
                          {},
                          true,
                          xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes"),
                          0};
        } else if (xml.name() == QLatin1String("source"))
            current.source = xml.readElementText();
        else if (xml.name() == QLatin1String("translation")) {
            const auto type = xml.attributes().value(QLatin1String("type"));
            current.finished = type.isEmpty();
            if (current.numerus) {
                while (!(xml.isEndElement() && xml.name() == QLatin1String("translation"))
                       && !xml.atEnd()) {
                    xml.readNext();
                    if (xml.isStartElement() && xml.name() == QLatin1String("numerusform")
                        && !xml.readElementText().isEmpty())
                        ++current.numerusForms;
                }
            } else {
                current.translation = xml.readElementText();
            }
            messages.append(current);
        }
    }
    return messages;
}

} // namespace

class TestGuiTranslations : public QObject {
    Q_OBJECT
private slots:
    void everyStringIsTranslated()
    {
        const QList<TsMessage> messages =
            readTs(QStringLiteral(STRATAMESH_TS_DIR "/stratamesh_fr.ts"));
        QVERIFY2(messages.size() > 40, qPrintable(QString::number(messages.size())));
        for (const TsMessage &m : messages) {
            QVERIFY2(m.finished, qPrintable(m.context + QLatin1String(": ") + m.source));
            if (m.numerus)
                QVERIFY2(m.numerusForms == 2, qPrintable(m.source)); // French: singular, plural
            else
                QVERIFY2(!m.translation.isEmpty(), qPrintable(m.source));
        }
    }

    void englishHasItsPluralForms()
    {
        int plurals = 0;
        for (const TsMessage &m : readTs(QStringLiteral(STRATAMESH_TS_DIR "/stratamesh_en.ts"))) {
            if (!m.numerus)
                continue; // English sources are the English text; only plurals need a translation
            ++plurals;
            QVERIFY2(m.finished && m.numerusForms == 2, qPrintable(m.source));
        }
        QVERIFY(plurals >= 5);
    }

    void tsFilesAreCurrentWithTheSources_data()
    {
        QTest::addColumn<QString>("ts");
        QTest::newRow("fr") << QStringLiteral(STRATAMESH_TS_DIR "/stratamesh_fr.ts");
        QTest::newRow("en") << QStringLiteral(STRATAMESH_TS_DIR "/stratamesh_en.ts");
    }

    void tsFilesAreCurrentWithTheSources()
    {
        QFETCH(QString, ts);
        QTemporaryDir dir;
        const QString fresh = dir.filePath(QStringLiteral("fresh_fr.ts"));
        QProcess lupdate;
        lupdate.setProcessChannelMode(QProcess::MergedChannels);
        lupdate.start(QStringLiteral(STRATAMESH_LUPDATE),
                      {QStringLiteral("-silent"), QStringLiteral("-no-obsolete"),
                       QStringLiteral("-locations"), QStringLiteral("none"),
                       QStringLiteral(STRATAMESH_GUI_SOURCE_DIR),
                       QStringLiteral(STRATAMESH_WIDGETS_SOURCE_DIR),
                       QStringLiteral(STRATAMESH_PARAMS_SOURCE_DIR),
                       QStringLiteral(STRATAMESH_MODEL_SOURCE_DIR),
                       QStringLiteral(STRATAMESH_REMESH_SOURCE_DIR),
                       QStringLiteral(STRATAMESH_IO_SOURCE_DIR),
                       QStringLiteral(STRATAMESH_VOLUME_SOURCE_DIR), QStringLiteral("-ts"), fresh});
        QVERIFY(lupdate.waitForFinished(60000));
        QVERIFY2(lupdate.exitCode() == 0, lupdate.readAll().constData());
        QSet<QString> expected, committed;
        for (const TsMessage &m : readTs(fresh))
            expected.insert(m.context + QLatin1Char('|') + m.source);
        for (const TsMessage &m : readTs(ts))
            committed.insert(m.context + QLatin1Char('|') + m.source);
        QVERIFY(!expected.isEmpty());
        for (const QString &key : expected)
            QVERIFY2(committed.contains(key),
                     qPrintable(QLatin1String("not in the .ts (run the lupdate target): ") + key));
        for (const QString &key : committed)
            QVERIFY2(expected.contains(key),
                     qPrintable(QLatin1String("obsolete in the .ts: ") + key));
    }

    void languageIsFoundBeforeTheFullParse()
    {
        QCOMPARE(languageArgument({QStringLiteral("stratamesh"), QStringLiteral("--lang"),
                                   QStringLiteral("FR")}),
                 QStringLiteral("fr"));
        QCOMPARE(languageArgument({QStringLiteral("stratamesh"), QStringLiteral("x.ml"),
                                   QStringLiteral("--lang=en")}),
                 QStringLiteral("en"));
        QCOMPARE(languageArgument({QStringLiteral("stratamesh"), QStringLiteral("--lang")}),
                 QString());
        GuiOptions options;
        int exitCode = -1;
        QVERIFY(!parseGuiOptions(
            {QStringLiteral("stratamesh"), QStringLiteral("--lang"), QStringLiteral("de")}, options,
            exitCode));
        QCOMPARE(exitCode, 2);
        QVERIFY(parseGuiOptions({QStringLiteral("stratamesh"), QStringLiteral("--lang"),
                                 QStringLiteral("fr"), QStringLiteral("--show-box"),
                                 QStringLiteral("m.ml")},
                                options, exitCode));
        QCOMPARE(options.language, QStringLiteral("fr"));
        QCOMPARE(options.openPath, QStringLiteral("m.ml"));
        QVERIFY(options.showBox);
        QVERIFY(!options.showEdges);
    }

    void englishPluralsAreLoaded()
    {
        QCOMPARE(installTranslations(QStringLiteral("en")), QStringLiteral("en"));
        QCOMPARE(QCoreApplication::translate("stratamesh::MainWindow", "%n surface(s)", nullptr, 1),
                 QStringLiteral("1 surface"));
        QCOMPARE(
            QCoreApplication::translate("stratamesh::MainWindow", "%n surface(s)", nullptr, 31),
            QStringLiteral("31 surfaces"));
    }

    // Runs last: the translator stays installed.
    void frenchIsLoadedAtRunTime()
    {
        QCOMPARE(installTranslations(QStringLiteral("fr")), QStringLiteral("fr"));
        // French uses the singular for zero.
        QCOMPARE(QCoreApplication::translate("stratamesh::MainWindow", "%n corner(s)", nullptr, 0),
                 QStringLiteral("0 coin"));
        MainWindow window;
        QStringList menus;
        for (QAction *action : window.menuBar()->actions())
            menus << action->text();
        QCOMPARE(menus, (QStringList{QStringLiteral("&Fichier"), QStringLiteral("É&dition"),
                                     QStringLiteral("&Affichage"), QStringLiteral("&Maillage"),
                                     QStringLiteral("A&nalyse"), QStringLiteral("&Aide")}));
        QCOMPARE(window.showBoxAction()->text(), QStringLiteral("Afficher la &boîte"));

        // Core's sentences too: a validity problem, with its values filled in after translation.
        Model model;
        Surface repeated;
        repeated.name = "h1";
        repeated.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        repeated.triangles = {{0, 1, 1}};
        model.surfaces.push_back(repeated);
        const ValidityReport report = checkValidity(model);
        QVERIFY(!report.problems.empty());
        const std::vector<Message> messages = validityMessages(report, QStringLiteral("m.ml"));
        QCOMPARE(messages.size(), report.problems.size());
        for (std::size_t i = 0; i < messages.size(); ++i) {
            QVERIFY(!report.problems[i].text.pattern.empty());
            QVERIFY2(messages[i].text != QString::fromStdString(report.problems[i].message),
                     qPrintable(messages[i].text));
        }
        const auto degenerate =
            std::find_if(messages.begin(), messages.end(), [](const Message &m) {
                return m.text.contains(QStringLiteral("utilise deux fois"));
            });
        QVERIFY(degenerate != messages.end());
        QCOMPARE(degenerate->text,
                 QStringLiteral("le triangle 0 de h1 utilise deux fois le même sommet"));

        // A ledger note, made in core and read back from a report (no pattern) alike.
        auto ledger = std::make_shared<SimplificationLedger>(2);
        setNote((*ledger)[0], {"strip %1 (%2 m wide, limit %3 m) removed before remeshing",
                               {"F2_a", "12", "40"}});
        (*ledger)[1].note = "surface entirely below the resolution";
        LedgerTableModel table;
        table.setLedger(ledger);
        QCOMPARE(table.index(0, LedgerTableModel::NoteColumn).data().toString(),
                 QStringLiteral("bande F2_a (12 m de large, limite 40 m) supprimée avant le "
                                "remaillage"));
        QCOMPARE(table.index(1, LedgerTableModel::NoteColumn).data().toString(),
                 QStringLiteral("surface entièrement sous la résolution"));
        // A value holding a place marker is not filled again.
        QCOMPARE(coreText({"region %1 has no boundary surface", {"%2"}}, {}),
                 QStringLiteral("la région %2 n'a aucune surface de bord"));
    }
};

QTEST_MAIN(TestGuiTranslations)
#include "test_gui_translations.moc"
