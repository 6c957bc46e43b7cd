#include "error_message.h"

#include "common/error.h"
#include "core_text.h"

namespace stratamesh {

Message errorMessage(const std::exception &e, const QString &file)
{
    if (const auto *f = dynamic_cast<const FileError *>(&e))
        return {Message::Severity::Error,
                coreText(f->text(), f->cause()),
                QString::fromStdString(f->file()),
                f->line(),
                {}};
    if (const auto *i = dynamic_cast<const InputError *>(&e); i && !i->text().pattern.empty())
        return {Message::Severity::Error, coreText(i->text(), i->what()), file, 0, {}};
    return {Message::Severity::Error, QString::fromStdString(e.what()), file, 0, {}};
}

} // namespace stratamesh
