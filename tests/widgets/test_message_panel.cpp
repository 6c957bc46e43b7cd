// The message panel lists severity, text and "file:line" for each message.
#include "message_panel.h"

#include <QSignalSpy>
#include <QtTest>

using namespace stratamesh;

class TestMessagePanel : public QObject {
    Q_OBJECT
private slots:
    void showsSeverityTextAndLocation()
    {
        MessagePanel panel;
        QSignalSpy counts(&panel, &MessagePanel::countChanged);
        panel.addMessage({Message::Severity::Error,
                          QStringLiteral("expected a number"),
                          QStringLiteral("/data/models/broken.ml"),
                          42,
                          {}});
        panel.addMessage({Message::Severity::Warning,
                          QStringLiteral("surface s1 is not sealed"),
                          QStringLiteral("/data/models/broken.ml"),
                          0,
                          {}});
        panel.addMessage({Message::Severity::Info, QStringLiteral("opened"), QString(), 0, {}});
        QCOMPARE(panel.count(), 3);
        QCOMPARE(counts.size(), 3);
        QCOMPARE(panel.count(Message::Severity::Error), 1);
        QCOMPARE(panel.count(Message::Severity::Warning), 1);
        QCOMPARE(panel.cellText(0, MessagePanel::LocationColumn), QStringLiteral("broken.ml:42"));
        QCOMPARE(panel.cellText(0, MessagePanel::TextColumn), QStringLiteral("expected a number"));
        QCOMPARE(panel.cellText(0, MessagePanel::SeverityColumn), QStringLiteral("Error"));
        QCOMPARE(panel.cellText(1, MessagePanel::LocationColumn), QStringLiteral("broken.ml"));
        QCOMPARE(panel.cellText(2, MessagePanel::LocationColumn), QString());
        QCOMPARE(panel.message(0).line, 42);
        QCOMPARE(panel.message(0).file, QStringLiteral("/data/models/broken.ml"));
        panel.clear();
        QCOMPARE(panel.count(), 0);
        QCOMPARE(counts.last().first().toInt(), 0);
    }

    void outOfRangeRowIsEmpty()
    {
        MessagePanel panel;
        QCOMPARE(panel.cellText(3, MessagePanel::TextColumn), QString());
        QCOMPARE(panel.message(-1).text, QString());
    }
};

QTEST_MAIN(TestMessagePanel)
#include "test_message_panel.moc"
