// A list of errors, warnings and notes with a severity icon, the text and "file:line".
#pragma once

#include "message.h"

#include <QWidget>

class QTreeWidget;

namespace stratamesh {

class MessagePanel : public QWidget {
    Q_OBJECT
public:
    enum Column { SeverityColumn, TextColumn, LocationColumn };

    explicit MessagePanel(QWidget *parent = nullptr);

    void addMessage(const Message &message);
    void clear();
    int count() const;
    int count(Message::Severity severity) const;
    Message message(int row) const;
    // As a click on the row does.
    void activate(int row);
    // The text shown in a cell, as a user reads it (for tests and copy).
    QString cellText(int row, Column column) const;

signals:
    void countChanged(int count);
    // The user clicked or activated a message (Enter, double-click).
    void messageActivated(const stratamesh::Message &message);

private:
    void retranslate();
    void changeEvent(QEvent *event) override;

    QTreeWidget *m_tree;
};

// "modelA2.ml:12", "modelA2.ml" or "" for a message without a file.
QString formatLocation(const Message &message);

} // namespace stratamesh
