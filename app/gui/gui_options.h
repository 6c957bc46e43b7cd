// Command line of the GUI: --open FILE, --screenshot PNG, --lang fr|en, --remesh-sites N,
// --complexity-cells N.
#pragma once

#include <QString>
#include <QStringList>

namespace stratamesh {

struct GuiOptions {
    QString openPath;       // empty: show the bundled sample model
    QString screenshotPath; // non-empty: load, render, save the window as PNG and exit
    QString language;       // "fr", "en", or empty for the system locale
    bool showBox = false;
    bool showEdges = false;
    int remeshSites = 0;     // > 0: remesh with this many sites once the model is open
    int complexityCells = 0; // > 0: measure the complexity with this many cells once it is open
};

// The value of --lang, looked up before the full parse so that --help is translated too.
QString languageArgument(const QStringList &arguments);

// Parses QCoreApplication::arguments(); on --help/--version or a bad option it prints and
// returns false with exitCode set.
bool parseGuiOptions(const QStringList &arguments, GuiOptions &options, int &exitCode);

} // namespace stratamesh
