#include "io/vtk_common.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkObject.h>

namespace stratamesh {

namespace {

void collect(vtkObject *, unsigned long event, void *clientData, void *callData)
{
    auto *message = static_cast<std::string *>(clientData);
    const char *text = static_cast<const char *>(callData);
    if ((event != vtkCommand::ErrorEvent && event != vtkCommand::WarningEvent) || !text)
        return;
    std::string line(text);
    while (!line.empty() && (line.back() == '\n' || line.back() == ' '))
        line.pop_back();
    // VTK prefixes "ERROR: In file, line N\nvtkClass (0x...): message": keep the message.
    const std::size_t colon = line.rfind("): ");
    if (colon != std::string::npos)
        line = line.substr(colon + 3);
    if (!message->empty())
        *message += "; ";
    *message += line;
}

} // namespace

VtkErrorCapture::VtkErrorCapture(vtkObject *object) : m_object(object)
{
    vtkNew<vtkCallbackCommand> error;
    error->SetCallback(collect);
    error->SetClientData(&m_message);
    m_errorTag = object->AddObserver(vtkCommand::ErrorEvent, error);
    // Observing warnings keeps them off the console; whether they fail is the caller's choice.
    vtkNew<vtkCallbackCommand> warning;
    warning->SetCallback(collect);
    warning->SetClientData(&m_warnings);
    m_warningTag = object->AddObserver(vtkCommand::WarningEvent, warning);
}

VtkErrorCapture::~VtkErrorCapture()
{
    m_object->RemoveObserver(m_errorTag);
    m_object->RemoveObserver(m_warningTag);
}

} // namespace stratamesh
