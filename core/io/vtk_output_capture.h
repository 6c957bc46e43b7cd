// Collects what VTK would print on the console (errors and warnings of a reader and of the
// readers it creates inside, which no observer on the outer object sees) for one read, so that
// a reader's complaint becomes our FileError instead of a raw print.
#pragma once

#include <string>

class vtkOutputWindow;

namespace stratamesh {

class VtkOutputCapture {
public:
    // Installs a capturing output window for the lifetime of this object; captures nest.
    VtkOutputCapture();
    ~VtkOutputCapture();
    VtkOutputCapture(const VtkOutputCapture &) = delete;
    VtkOutputCapture &operator=(const VtkOutputCapture &) = delete;

    // Errors and warnings, without VTK's "file, line" and object prefixes, joined by "; ".
    std::string message() const;
    bool failed() const { return !message().empty(); }

private:
    vtkOutputWindow *m_previous = nullptr;
    vtkOutputWindow *m_window = nullptr;
    int m_loggerVerbosity = 0;
};

} // namespace stratamesh
