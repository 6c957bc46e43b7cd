// File > Open Recent: the last models and projects opened, most recent first, kept in the settings
// (app_settings.h) so that the list outlives the window. A file gone since is listed disabled, its
// tooltip saying so; Clear Menu empties the list.
#pragma once

#include <QObject>
#include <QStringList>

class QAction;
class QMenu;
class QWidget;

namespace stratamesh {

class RecentFiles : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxFiles = 8;

    explicit RecentFiles(QWidget *parent);

    QMenu *menu() const { return m_menu; }
    QAction *clearAction() const { return m_clear; }
    // Absolute paths, most recent first, as the settings hold them now.
    QStringList paths() const;
    // Moves `path` to the top (a sample model, with no file, is not listed).
    void add(const QString &path);
    void clear();
    // Lists the files again: some may have gone since (done each time the menu opens).
    void refresh();
    void setEnabled(bool enabled);
    void retranslate();

signals:
    void openRequested(const QString &path);

private:
    void store(const QStringList &paths);

    QMenu *m_menu;
    QAction *m_clear;
    bool m_enabled = true;
};

} // namespace stratamesh
