#include "io/vtk_common.h"
#include "common/translate_noop.h"

#include <vtkCallbackCommand.h>
#include <vtkCellType.h>
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

// How many point ids a cell of this VTK type has; 0 for "at least one" (poly types), -1 for a
// type StrataMesh does not exchange.
int pointCountOf(int type)
{
    switch (type) {
    case VTK_TETRA:
        return 4;
    case VTK_PYRAMID:
        return 5;
    case VTK_WEDGE:
        return 6;
    case VTK_TRIANGLE:
        return 3;
    case VTK_LINE:
        return 2;
    case VTK_VERTEX:
        return 1;
    case VTK_POLY_LINE:
    case VTK_POLY_VERTEX:
        return 0;
    default:
        return -1;
    }
}

} // namespace

MessageText vtkCellProblem(long long cell, int type, const long long *ids, long long count,
                           long long points)
{
    const int expected = pointCountOf(type);
    const std::string c = std::to_string(cell), t = std::to_string(type);
    if ((expected > 0 && count != expected) || count < 1 || (type == VTK_POLY_LINE && count < 2)) {
        if (expected > 0)
            return {QT_TRANSLATE_NOOP("stratamesh::Core", "cell %1 (numbered from 0, VTK type %2) "
                                                          "has %3 point ids, its type needs %4"),
                    {c, t, std::to_string(count), std::to_string(expected)}};
        return {QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "cell %1 (numbered from 0, VTK type %2) has %3 point ids"),
                {c, t, std::to_string(count)}};
    }
    if (expected < 0)
        return {QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "cell %1 has VTK type %2, which StrataMesh does not exchange "
                                  "(tets, pyramids, wedges, triangles, lines and vertices only)"),
                {c, t}};
    for (long long k = 0; k < count; ++k)
        if (ids[k] < 0 || ids[k] >= points)
            return {QT_TRANSLATE_NOOP("stratamesh::Core", "cell %1 uses point %2 of %3"),
                    {c, std::to_string(ids[k]), std::to_string(points)}};
    return {};
}

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
