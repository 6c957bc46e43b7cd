#include "io/vtk_output_capture.h"

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <mutex>

namespace stratamesh {

namespace {

// VTK formats "ERROR: In /path/file.cxx, line N\nvtkClass (0x...): message" (or "Generic
// Warning: In ..." without the class): keep the message.
std::string withoutPrefix(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    const std::size_t newline = text.find('\n');
    if (newline != std::string::npos && text.find(", line ") < newline)
        text = text.substr(newline + 1);
    const std::size_t colon = text.find("): ");
    if (colon != std::string::npos && text.compare(0, 3, "vtk") == 0)
        text = text.substr(colon + 3);
    for (char &c : text)
        if (c == '\n')
            c = ' ';
    return text;
}

class CapturingWindow : public vtkOutputWindow {
public:
    static CapturingWindow *New();
    vtkTypeMacro(CapturingWindow, vtkOutputWindow);

    void DisplayText(const char *) override {}
    void DisplayDebugText(const char *) override {}
    void DisplayErrorText(const char *text) override { add(text); }
    void DisplayWarningText(const char *text) override { add(text); }
    void DisplayGenericWarningText(const char *text) override { add(text); }

    std::string message() const
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_message;
    }

private:
    void add(const char *text)
    {
        if (!text)
            return;
        std::lock_guard<std::mutex> lock(m_mutex);
        if (!m_message.empty())
            m_message += "; ";
        m_message += withoutPrefix(text);
    }
    mutable std::mutex m_mutex;
    std::string m_message;
};

vtkStandardNewMacro(CapturingWindow);

// The output window is process-wide: reads on several threads take turns installing theirs.
std::recursive_mutex &installMutex()
{
    static std::recursive_mutex mutex;
    return mutex;
}

} // namespace

VtkOutputCapture::VtkOutputCapture()
{
    installMutex().lock();
    m_previous = vtkOutputWindow::GetInstance();
    m_previous->Register(nullptr);
    m_window = CapturingWindow::New();
    vtkOutputWindow::SetInstance(m_window);
    // VTK's logger prints the same message on stderr before the output window gets it.
    m_loggerVerbosity = static_cast<int>(vtkLogger::GetCurrentVerbosityCutoff());
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkOutputCapture::~VtkOutputCapture()
{
    vtkLogger::SetStderrVerbosity(static_cast<vtkLogger::Verbosity>(m_loggerVerbosity));
    vtkOutputWindow::SetInstance(m_previous);
    m_previous->UnRegister(nullptr);
    m_window->Delete();
    installMutex().unlock();
}

std::string VtkOutputCapture::message() const
{
    return static_cast<CapturingWindow *>(m_window)->message();
}

} // namespace stratamesh
