#include "validity_messages.h"

#include "core_text.h"

#include <QCoreApplication>

#include <map>

namespace stratamesh {

std::vector<Message> validityMessages(const ValidityReport &report, const QString &file)
{
    std::vector<Message> messages;
    std::map<std::string, std::size_t> listed;
    for (const ValidityProblem &problem : report.problems) {
        Message m;
        m.severity = Message::Severity::Warning;
        m.text = coreText(problem.text, problem.message);
        m.file = file;
        m.position = problem.position;
        messages.push_back(m);
        ++listed[problem.check];
    }
    // The report lists a bounded number of problems per check but counts them all.
    for (const auto &[check, count] : report.counts) {
        const std::size_t shown = listed[check];
        if (count <= shown)
            continue;
        Message m;
        m.severity = Message::Severity::Warning;
        m.text =
            QCoreApplication::translate("ValidityMessages", "… and %1 more problems of kind “%2”")
                .arg(qulonglong(count - shown))
                .arg(QString::fromStdString(check));
        m.file = file;
        messages.push_back(m);
    }
    if (!report.valid && messages.empty()) {
        Message m;
        m.severity = Message::Severity::Warning;
        m.text = QCoreApplication::translate("ValidityMessages", "The model is not valid");
        m.file = file;
        messages.push_back(m);
    }
    return messages;
}

} // namespace stratamesh
