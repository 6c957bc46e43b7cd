#include "gui_options.h"

#include "params/param_tables.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace stratamesh {

QString languageArgument(const QStringList &arguments)
{
    for (int i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        if ((a == QLatin1String("--lang") || a == QLatin1String("-lang"))
            && i + 1 < arguments.size())
            return arguments[i + 1].toLower();
        if (a.startsWith(QLatin1String("--lang=")))
            return a.mid(7).toLower();
    }
    return {};
}

bool parseGuiOptions(const QStringList &arguments, GuiOptions &options, int &exitCode)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "GuiOptions", "StrataMesh: remeshing and meshing of 3D structural models."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption open(
        QStringLiteral("open"),
        QCoreApplication::translate("GuiOptions",
                                    "Open the model or the project (.smproj) in <file>."),
        QStringLiteral("file"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate(
            "GuiOptions", "Load the model, save the window as a PNG image in <png> and exit "
                          "(status 0 when saved, 1 when the image could not be written, 2 when the "
                          "model could not be opened)."),
        QStringLiteral("png"));
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QCoreApplication::translate("GuiOptions", "User interface language: fr or en."),
        QStringLiteral("language"));
    const QCommandLineOption showBox(
        QStringLiteral("show-box"),
        QCoreApplication::translate("GuiOptions", "Start with the box surfaces shown."));
    const QCommandLineOption showEdges(
        QStringLiteral("show-edges"),
        QCoreApplication::translate("GuiOptions", "Start with triangle edges shown."));
    const QCommandLineOption remeshSites(
        QStringLiteral("remesh-sites"),
        QCoreApplication::translate(
            "GuiOptions", "Remesh the model with <n> sites once it is open (with --screenshot, the "
                          "picture shows the result with its first simplification selected)."),
        QStringLiteral("n"));
    parser.addOption(remeshSites);
    const QCommandLineOption complexityCells(
        QStringLiteral("complexity-cells"),
        QCoreApplication::translate(
            "GuiOptions",
            "Measure the complexity of the model with <n> cells once it is open (with "
            "--screenshot, the picture shows the heat map and the Complexity dock)."),
        QStringLiteral("n"));
    parser.addOption(complexityCells);
    parser.addOption(showBox);
    parser.addOption(showEdges);
    parser.addOption(open);
    parser.addOption(screenshot);
    parser.addOption(lang);
    parser.addPositionalArgument(
        QStringLiteral("file"),
        QCoreApplication::translate("GuiOptions", "Model to open (same as --open)."),
        QStringLiteral("[file]"));
    if (!parser.parse(arguments)) {
        std::fprintf(stderr, "%s\n", qPrintable(parser.errorText()));
        exitCode = 2;
        return false;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        std::printf("%s", qPrintable(parser.helpText()));
        exitCode = 0;
        return false;
    }
    if (parser.isSet(QStringLiteral("version"))) {
        std::printf("%s %s\n", qPrintable(QCoreApplication::applicationName()),
                    qPrintable(QCoreApplication::applicationVersion()));
        exitCode = 0;
        return false;
    }
    options.openPath = parser.value(open);
    if (options.openPath.isEmpty() && !parser.positionalArguments().isEmpty())
        options.openPath = parser.positionalArguments().constFirst();
    options.screenshotPath = parser.value(screenshot);
    options.showBox = parser.isSet(showBox);
    options.showEdges = parser.isSet(showEdges);
    options.language = parser.value(lang).toLower();
    // The ranges of the `sites` and `cells` entries of the parameter tables, as everywhere.
    auto count = [&](const QCommandLineOption &option, const ParamInfo &range, int &value,
                     const char *message) {
        if (!parser.isSet(option))
            return true;
        bool ok = false;
        value = parser.value(option).toInt(&ok);
        if (ok && value >= range.minimum && value <= range.maximum)
            return true;
        std::fprintf(stderr, "%s\n",
                     qPrintable(QCoreApplication::translate("GuiOptions", message)
                                    .arg(QString::fromStdString(formatParamNumber(range.minimum)),
                                         QString::fromStdString(formatParamNumber(range.maximum)),
                                         parser.value(option))));
        exitCode = 2;
        return false;
    };
    if (!count(remeshSites, remeshParamTable().info("sites"), options.remeshSites,
               QT_TRANSLATE_NOOP("GuiOptions", "--remesh-sites needs a number of sites in "
                                               "[%1, %2], not '%3'.")))
        return false;
    if (!count(complexityCells, complexityParamTable().info("cells"), options.complexityCells,
               QT_TRANSLATE_NOOP("GuiOptions", "--complexity-cells needs a number of cells in "
                                               "[%1, %2], not '%3'.")))
        return false;
    if (!options.language.isEmpty() && options.language != QLatin1String("fr")
        && options.language != QLatin1String("en")) {
        std::fprintf(stderr, "%s\n",
                     qPrintable(QCoreApplication::translate("GuiOptions",
                                                            "Unknown language '%1': use fr or en.")
                                    .arg(options.language)));
        exitCode = 2;
        return false;
    }
    return true;
}

} // namespace stratamesh
