// Command line of the GUI: --open FILE, --screenshot PNG, --lang fr|en, and the scripted steps
// (--run complexity|remesh|tetmesh|hybrid with --cells/--sites, --colour-by, --save-project, and
// the older --remesh-sites N / --complexity-cells N), run in the order given.
#pragma once

#include <QString>
#include <QStringList>

#include <vector>

namespace stratamesh {

// One step of a scripted session, done once the model is open and the step before has finished.
struct ScriptStep {
    enum class Kind { Complexity, Remesh, Tetmesh, Hybrid, ColourBy, SaveProject };
    Kind kind = Kind::Remesh;
    int count = 0; // cells (complexity) or sites (remesh, hybrid); 0: the dialog's default
    QString value; // the colouring (entity, min-angle, quality, distance) or the project path
};

// The step as it was written on the command line ("--run remesh --sites 300"), for messages.
QString describeStep(const ScriptStep &step);

struct GuiOptions {
    QString openPath;       // empty: show the bundled sample model
    QString screenshotPath; // non-empty: load, run the steps, save the window as PNG and exit
    QString language;       // "fr", "en", or empty for the system locale
    bool showBox = false;
    bool showEdges = false;
    std::vector<ScriptStep> steps; // in command-line order
};

// The value of --lang, looked up before the full parse so that --help is translated too.
QString languageArgument(const QStringList &arguments);

// Parses QCoreApplication::arguments(); on --help/--version or a bad option it prints and
// returns false with exitCode set.
bool parseGuiOptions(const QStringList &arguments, GuiOptions &options, int &exitCode);

} // namespace stratamesh
