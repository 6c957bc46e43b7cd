// The French translation is complete, current with the sources, and loaded at run time.
#include "gui_options.h"
#include "main_window.h"
#include "translations.h"

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
                       QStringLiteral(STRATAMESH_PARAMS_SOURCE_DIR), QStringLiteral("-ts"), fresh});
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
    }
};

QTEST_MAIN(TestGuiTranslations)
#include "test_gui_translations.moc"
