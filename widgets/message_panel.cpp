#include "message_panel.h"

#include <QApplication>
#include <QEvent>
#include <QFileInfo>
#include <QHeaderView>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace stratamesh {

namespace {

constexpr int kMessageRole = Qt::UserRole + 1;

QIcon severityIcon(Message::Severity severity, const QStyle *style)
{
    switch (severity) {
    case Message::Severity::Error:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    case Message::Severity::Warning:
        return style->standardIcon(QStyle::SP_MessageBoxWarning);
    case Message::Severity::Info:
        break;
    }
    return style->standardIcon(QStyle::SP_MessageBoxInformation);
}

QString severityName(Message::Severity severity)
{
    switch (severity) {
    case Message::Severity::Error:
        return MessagePanel::tr("Error");
    case Message::Severity::Warning:
        return MessagePanel::tr("Warning");
    case Message::Severity::Info:
        break;
    }
    return MessagePanel::tr("Info");
}

} // namespace

QString formatLocation(const Message &message)
{
    if (message.file.isEmpty())
        return {};
    const QString name = QFileInfo(message.file).fileName();
    return message.line > 0 ? QStringLiteral("%1:%2").arg(name).arg(message.line) : name;
}

MessagePanel::MessagePanel(QWidget *parent) : QWidget(parent), m_tree(new QTreeWidget(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tree);
    m_tree->setColumnCount(3);
    m_tree->setRootIsDecorated(false);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(SeverityColumn, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(TextColumn, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(LocationColumn, QHeaderView::ResizeToContents);
    const auto activated = [this](QTreeWidgetItem *item) {
        emit messageActivated(item->data(0, kMessageRole).value<Message>());
    };
    connect(m_tree, &QTreeWidget::itemClicked, this, activated);
    connect(m_tree, &QTreeWidget::itemActivated, this, activated);
    retranslate();
}

void MessagePanel::retranslate()
{
    m_tree->setHeaderLabels({tr("Severity"), tr("Message"), tr("Location")});
    for (int row = 0; row < m_tree->topLevelItemCount(); ++row) {
        QTreeWidgetItem *item = m_tree->topLevelItem(row);
        item->setText(SeverityColumn,
                      severityName(item->data(0, kMessageRole).value<Message>().severity));
    }
}

void MessagePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void MessagePanel::addMessage(const Message &message)
{
    auto *item = new QTreeWidgetItem;
    item->setData(0, kMessageRole, QVariant::fromValue(message));
    item->setIcon(SeverityColumn, severityIcon(message.severity, style()));
    item->setText(SeverityColumn, severityName(message.severity));
    item->setText(TextColumn, message.text);
    item->setToolTip(TextColumn, message.text);
    item->setText(LocationColumn, formatLocation(message));
    item->setToolTip(LocationColumn, message.file);
    if (message.position)
        item->setToolTip(TextColumn, tr("%1\nClick to show it in the views").arg(message.text));
    m_tree->addTopLevelItem(item);
    m_tree->scrollToItem(item);
    emit countChanged(count());
}

void MessagePanel::clear()
{
    m_tree->clear();
    emit countChanged(0);
}

int MessagePanel::count() const
{
    return m_tree->topLevelItemCount();
}

int MessagePanel::count(Message::Severity severity) const
{
    int n = 0;
    for (int row = 0; row < count(); ++row)
        n += message(row).severity == severity ? 1 : 0;
    return n;
}

Message MessagePanel::message(int row) const
{
    const QTreeWidgetItem *item = m_tree->topLevelItem(row);
    return item ? item->data(0, kMessageRole).value<Message>() : Message{};
}

void MessagePanel::activate(int row)
{
    if (QTreeWidgetItem *item = m_tree->topLevelItem(row)) {
        m_tree->setCurrentItem(item);
        emit messageActivated(item->data(0, kMessageRole).value<Message>());
    }
}

QString MessagePanel::cellText(int row, Column column) const
{
    const QTreeWidgetItem *item = m_tree->topLevelItem(row);
    return item ? item->text(column) : QString();
}

} // namespace stratamesh
