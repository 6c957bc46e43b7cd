#include "error_message.h"

#include "common/error.h"

namespace stratamesh {

Message errorMessage(const std::exception &e, const QString &file)
{
    if (const auto *f = dynamic_cast<const FileError *>(&e))
        return {Message::Severity::Error,
                QString::fromStdString(f->cause()),
                QString::fromStdString(f->file()),
                f->line(),
                {}};
    return {Message::Severity::Error, QString::fromStdString(e.what()), file, 0, {}};
}

} // namespace stratamesh
