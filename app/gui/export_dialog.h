// File > Export…'s dialog: what to export (the open model, its remesh, a TetGen or hybrid mesh;
// an entry that cannot be exported now says why in its tooltip), the format (every writer of
// io/formats.h that takes it; the others disabled with the reason), the writer's options
// (Gmsh version and SaveAll, the surface of a single-surface format), the file, whose extension
// follows the format, and a warning line with what the format loses, from the format table.
#pragma once

#include "io/formats.h"

#include <QDialog>
#include <QList>
#include <QStringList>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace stratamesh {

// One thing the dialog offers to export.
struct ExportSubject {
    QString label;
    QString unavailable; // why it cannot be exported now; empty when it can
    ExportData data = ExportData::SurfaceModel;
    QStringList surfaceNames; // of a surface model: single-surface formats write one of them
    QString baseName;         // the file name offered, without extension
};

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // `directory`: where the file goes unless the user picks another folder.
    ExportDialog(const QList<ExportSubject> &subjects, const QString &directory,
                 QWidget *parent = nullptr);

    int subject() const;
    void setSubject(int index);
    // The chosen row of fileFormats(), or nullptr when none fits the subject.
    const FileFormat *format() const;
    // By extension (".msh"); false when no enabled entry has it.
    bool setFormat(const QString &extension);
    ExportOptions options() const;
    // The target, its extension that of the format.
    QString path() const;
    void setPath(const QString &path);
    // What the chosen format loses of the chosen subject, as shown; empty when nothing.
    QString warning() const;

    QComboBox *subjectBox() const { return m_subject; }
    QComboBox *formatBox() const { return m_format; }
    QComboBox *mshVersionBox() const { return m_mshVersion; }
    QCheckBox *saveAllBox() const { return m_saveAll; }
    QComboBox *surfaceBox() const { return m_surface; }
    QLineEdit *pathEdit() const { return m_path; }
    QLabel *warningLabel() const { return m_warning; }
    QPushButton *exportButton() const { return m_export; }

    // Why `format` cannot take `data`, in words; empty when it can.
    static QString refusal(const FileFormat &format, ExportData data);
    // What `format` loses of `data`, as one sentence; empty when nothing. A model of one surface
    // loses no other surface to a single-surface format.
    static QString lossSentence(const FileFormat &format, ExportData data, int surfaceCount = 2);

private:
    void updateFormats();
    void updateOptions();
    void followFormat();
    void followPath();
    void browse();
    void updateState();

    QList<ExportSubject> m_subjects;
    QFormLayout *m_form;
    QComboBox *m_subject;
    QComboBox *m_format;
    QComboBox *m_mshVersion;
    QCheckBox *m_saveAll;
    QComboBox *m_surface;
    QLineEdit *m_path;
    QPushButton *m_browse;
    QLabel *m_warning;
    QPushButton *m_export;
};

} // namespace stratamesh
