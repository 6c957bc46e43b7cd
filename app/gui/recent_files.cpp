#include "recent_files.h"

#include "app_settings.h"
#include "disabled_reason.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace stratamesh {

namespace {

const QString kKey = QStringLiteral("recentFiles");

} // namespace

RecentFiles::RecentFiles(QWidget *parent)
    : QObject(parent), m_menu(new QMenu(parent)), m_clear(new QAction(this))
{
    m_menu->setObjectName(QStringLiteral("RecentFilesMenu"));
    m_menu->setToolTipsVisible(true); // "File not found" on a file gone
    connect(m_menu, &QMenu::aboutToShow, this, &RecentFiles::refresh);
    connect(m_clear, &QAction::triggered, this, &RecentFiles::clear);
    setDisabledReason(m_clear, [] { return tr("no file opened yet"); });
    retranslate();
}

QStringList RecentFiles::paths() const
{
    return openSettings()->value(kKey).toStringList();
}

void RecentFiles::add(const QString &path)
{
    if (path.isEmpty())
        return;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList list = paths();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > kMaxFiles)
        list.removeLast();
    store(list);
}

void RecentFiles::clear()
{
    store({});
}

void RecentFiles::store(const QStringList &list)
{
    openSettings()->setValue(kKey, list);
    refresh();
}

void RecentFiles::refresh()
{
    m_menu->clear(); // deletes the file actions, which the menu owns; m_clear is ours
    const QStringList list = paths();
    for (int i = 0; i < list.size(); ++i) {
        const QString &path = list[i];
        const QString native = QDir::toNativeSeparators(path);
        // &1 … &8: the keyboard reaches each entry.
        QAction *action =
            m_menu->addAction(tr("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
        action->setData(path);
        action->setStatusTip(native);
        if (QFileInfo::exists(path)) {
            action->setToolTip(native);
            action->setEnabled(m_enabled);
            connect(action, &QAction::triggered, this, [this, path] { emit openRequested(path); });
        } else {
            action->setToolTip(tr("File not found: %1").arg(native));
            action->setEnabled(false);
        }
    }
    m_menu->addSeparator();
    m_menu->addAction(m_clear);
    m_clear->setEnabled(!list.isEmpty());
}

void RecentFiles::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    refresh();
}

void RecentFiles::retranslate()
{
    m_menu->setTitle(tr("Open &Recent"));
    m_clear->setText(tr("&Clear Menu"));
    m_clear->setStatusTip(tr("Forget the files opened before"));
}

} // namespace stratamesh
