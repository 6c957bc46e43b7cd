#include "gui_options.h"

#include "params/param_tables.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace stratamesh {

namespace {

void complain(const QString &text)
{
    std::fprintf(stderr, "%s\n", qPrintable(text));
}

// `text` as a count in the range of a parameter table's entry, or a message naming the option.
bool readCount(const QString &option, const QString &text, const ParamInfo &range, int &value)
{
    bool ok = false;
    value = text.toInt(&ok);
    if (ok && value >= range.minimum && value <= range.maximum)
        return true;
    complain(QCoreApplication::translate("GuiOptions", "%1 needs a number in [%2, %3], not '%4'.")
                 .arg(option, QString::fromStdString(formatParamNumber(range.minimum)),
                      QString::fromStdString(formatParamNumber(range.maximum)), text));
    return false;
}

// QCommandLineParser keeps the values of each option but not the order between options: the steps
// are read again from the arguments, in order ("--name value" and "--name=value").
bool readSteps(const QStringList &arguments, std::vector<ScriptStep> &steps)
{
    static const QStringList withValue = {
        QStringLiteral("open"),         QStringLiteral("screenshot"),
        QStringLiteral("lang"),         QStringLiteral("run"),
        QStringLiteral("sites"),        QStringLiteral("cells"),
        QStringLiteral("colour-by"),    QStringLiteral("save-project"),
        QStringLiteral("remesh-sites"), QStringLiteral("complexity-cells")};
    static const QStringList colourings = {QStringLiteral("entity"), QStringLiteral("min-angle"),
                                           QStringLiteral("quality"), QStringLiteral("distance")};
    using Kind = ScriptStep::Kind;
    const ParamInfo &remeshSites = remeshParamTable().info("sites");
    const ParamInfo &hybridSites = hybridParamTable().info("sites");
    const ParamInfo &cells = complexityParamTable().info("cells");
    for (int i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        if (a == QLatin1String("--"))
            break;
        if (!a.startsWith(QLatin1String("--")))
            continue;
        QString name = a.mid(2), value;
        const int equals = name.indexOf(QLatin1Char('='));
        if (equals >= 0) {
            value = name.mid(equals + 1);
            name.truncate(equals);
        } else if (withValue.contains(name) && i + 1 < arguments.size()) {
            value = arguments[++i];
        }
        ScriptStep *last = steps.empty() ? nullptr : &steps.back();
        if (name == QLatin1String("run")) {
            ScriptStep step;
            const QString what = value.toLower();
            if (what == QLatin1String("complexity"))
                step.kind = Kind::Complexity;
            else if (what == QLatin1String("remesh"))
                step.kind = Kind::Remesh;
            else if (what == QLatin1String("tetmesh"))
                step.kind = Kind::Tetmesh;
            else if (what == QLatin1String("hybrid"))
                step.kind = Kind::Hybrid;
            else {
                complain(QCoreApplication::translate(
                             "GuiOptions",
                             "Unknown step '%1' for --run: use complexity, remesh, tetmesh or "
                             "hybrid.")
                             .arg(value));
                return false;
            }
            steps.push_back(step);
        } else if (name == QLatin1String("sites")) {
            if (!last || (last->kind != Kind::Remesh && last->kind != Kind::Hybrid)
                || last->count > 0) {
                complain(QCoreApplication::translate(
                    "GuiOptions", "--sites must follow --run remesh or --run hybrid."));
                return false;
            }
            if (!readCount(QStringLiteral("--sites"), value,
                           last->kind == Kind::Remesh ? remeshSites : hybridSites, last->count))
                return false;
        } else if (name == QLatin1String("cells")) {
            if (!last || last->kind != Kind::Complexity || last->count > 0) {
                complain(QCoreApplication::translate("GuiOptions",
                                                     "--cells must follow --run complexity."));
                return false;
            }
            if (!readCount(QStringLiteral("--cells"), value, cells, last->count))
                return false;
        } else if (name == QLatin1String("remesh-sites")
                   || name == QLatin1String("complexity-cells")) {
            ScriptStep step;
            const bool remesh = name == QLatin1String("remesh-sites");
            step.kind = remesh ? Kind::Remesh : Kind::Complexity;
            if (!readCount(QLatin1String("--") + name, value, remesh ? remeshSites : cells,
                           step.count))
                return false;
            steps.push_back(step);
        } else if (name == QLatin1String("colour-by")) {
            if (!colourings.contains(value.toLower())) {
                complain(QCoreApplication::translate(
                             "GuiOptions",
                             "Unknown colouring '%1' for --colour-by: use entity, min-angle, "
                             "quality or distance.")
                             .arg(value));
                return false;
            }
            steps.push_back({Kind::ColourBy, 0, value.toLower()});
        } else if (name == QLatin1String("save-project")) {
            if (value.isEmpty()) {
                complain(
                    QCoreApplication::translate("GuiOptions", "--save-project needs a file name."));
                return false;
            }
            steps.push_back({Kind::SaveProject, 0, value});
        }
    }
    return true;
}

} // namespace

QString describeStep(const ScriptStep &step)
{
    using Kind = ScriptStep::Kind;
    const QString count = step.count > 0 ? QString::number(step.count) : QString();
    switch (step.kind) {
    case Kind::Complexity:
        return QStringLiteral("--run complexity")
               + (count.isEmpty() ? QString() : QLatin1String(" --cells ") + count);
    case Kind::Remesh:
        return QStringLiteral("--run remesh")
               + (count.isEmpty() ? QString() : QLatin1String(" --sites ") + count);
    case Kind::Tetmesh:
        return QStringLiteral("--run tetmesh");
    case Kind::Hybrid:
        return QStringLiteral("--run hybrid")
               + (count.isEmpty() ? QString() : QLatin1String(" --sites ") + count);
    case Kind::ColourBy:
        return QStringLiteral("--colour-by ") + step.value;
    case Kind::SaveProject:
        return QStringLiteral("--save-project ") + step.value;
    }
    return {};
}

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
            "GuiOptions",
            "Load the model, do the steps, save the window as a PNG image in <png> and exit "
            "(status 0 when saved, 1 when the image could not be written, 2 when the "
            "model could not be opened, 3 when a step failed)."),
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
        QCoreApplication::translate("GuiOptions", "Same as --run remesh --sites <n>."),
        QStringLiteral("n"));
    parser.addOption(remeshSites);
    const QCommandLineOption complexityCells(
        QStringLiteral("complexity-cells"),
        QCoreApplication::translate("GuiOptions", "Same as --run complexity --cells <n>."),
        QStringLiteral("n"));
    parser.addOption(complexityCells);
    const QCommandLineOption run(
        QStringLiteral("run"),
        QCoreApplication::translate(
            "GuiOptions",
            "Once the model is open, run <step>: complexity, remesh, tetmesh (the input and the "
            "remesh) or hybrid; may be repeated. The steps, --colour-by and --save-project are "
            "done in the order given, each once the one before has finished; a failed step "
            "stops the others, prints its name and exits with status 3 (after the screenshot, "
            "if asked)."),
        QStringLiteral("step"));
    parser.addOption(run);
    const QCommandLineOption sites(
        QStringLiteral("sites"),
        QCoreApplication::translate("GuiOptions",
                                    "Number of sites of the --run remesh or --run hybrid "
                                    "just before."),
        QStringLiteral("n"));
    parser.addOption(sites);
    const QCommandLineOption cells(
        QStringLiteral("cells"),
        QCoreApplication::translate("GuiOptions",
                                    "Number of cells of the --run complexity just before."),
        QStringLiteral("n"));
    parser.addOption(cells);
    const QCommandLineOption colourBy(
        QStringLiteral("colour-by"),
        QCoreApplication::translate(
            "GuiOptions", "Colour both views by <colouring>: entity, min-angle, quality or "
                          "distance (needs a remesh before)."),
        QStringLiteral("colouring"));
    parser.addOption(colourBy);
    const QCommandLineOption saveProject(
        QStringLiteral("save-project"),
        QCoreApplication::translate("GuiOptions",
                                    "Save the runs made so far as the project <project>.smproj."),
        QStringLiteral("project"));
    parser.addOption(saveProject);
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
    if (!readSteps(arguments, options.steps)) {
        exitCode = 2;
        return false;
    }
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
