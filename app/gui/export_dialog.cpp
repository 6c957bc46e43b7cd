#include "export_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardItemModel>
#include <QVBoxLayout>

namespace stratamesh {

namespace {

// The path with `extension` in place of a format extension it has, else appended: "a.vtu" →
// "a.msh", "a" → "a.msh", "a.b" → "a.b.msh".
QString withExtension(const QString &path, const QString &extension)
{
    if (path.isEmpty())
        return path;
    const std::string p = path.toStdString();
    const std::string current = fileExtension(p);
    if (current == extension.toStdString())
        return path;
    QString stem = path;
    if (!current.empty() && findFormat(p) != nullptr)
        stem.chop(int(current.size()));
    return stem + extension;
}

void setEntryEnabled(QComboBox *box, int index, bool enabled, const QString &tooltip)
{
    auto *model = qobject_cast<QStandardItemModel *>(box->model());
    if (QStandardItem *item = model ? model->item(index) : nullptr)
        item->setEnabled(enabled);
    box->setItemData(index, tooltip.isEmpty() ? QVariant() : QVariant(tooltip), Qt::ToolTipRole);
}

bool entryEnabled(const QComboBox *box, int index)
{
    const auto *model = qobject_cast<const QStandardItemModel *>(box->model());
    const QStandardItem *item = model ? model->item(index) : nullptr;
    return item != nullptr && item->isEnabled();
}

} // namespace

ExportDialog::ExportDialog(const QList<ExportSubject> &subjects, const QString &directory,
                           QWidget *parent)
    : QDialog(parent), m_subjects(subjects), m_form(new QFormLayout),
      m_subject(new QComboBox(this)), m_format(new QComboBox(this)),
      m_mshVersion(new QComboBox(this)), m_saveAll(new QCheckBox(this)),
      m_surface(new QComboBox(this)), m_path(new QLineEdit(this)), m_browse(new QPushButton(this)),
      m_warning(new QLabel(this))
{
    setObjectName(QStringLiteral("ExportDialog"));
    setWindowTitle(tr("Export"));

    for (int i = 0; i < m_subjects.size(); ++i) {
        m_subject->addItem(m_subjects[i].label);
        setEntryEnabled(m_subject, i, m_subjects[i].unavailable.isEmpty(),
                        m_subjects[i].unavailable);
    }
    for (const FileFormat *f : formatsFor(FormatUse::Export))
        m_format->addItem(tr("%1 (*%2)").arg(QString::fromUtf8(f->name), f->extension),
                          QString::fromUtf8(f->extension));
    m_mshVersion->addItem(tr("4.1 (Gmsh 4)"), int(GmshWriteOptions::Version::V41));
    m_mshVersion->addItem(tr("2.2 (older readers)"), int(GmshWriteOptions::Version::V22));
    m_saveAll->setText(tr("Keep elements without a group (Gmsh Mesh.SaveAll)"));
    m_saveAll->setToolTip(tr("Gmsh keeps only elements of a physical group; this writes the "
                             "others too, in an entity without one"));
    m_browse->setText(tr("&Browse…"));
    m_warning->setObjectName(QStringLiteral("ExportWarning"));
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #a05a00;"));

    auto *file = new QHBoxLayout;
    file->addWidget(m_path, 1);
    file->addWidget(m_browse);
    m_form->addRow(tr("&Export:"), m_subject);
    m_form->addRow(tr("&Format:"), m_format);
    m_form->addRow(tr("MSH &version:"), m_mshVersion);
    m_form->addRow(QString(), m_saveAll);
    m_form->addRow(tr("&Surface:"), m_surface);
    auto *fileLabel = new QLabel(tr("F&ile:"), this);
    fileLabel->setBuddy(m_path); // a row of a layout gets no buddy of its own
    m_form->addRow(fileLabel, file);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_export = buttons->button(QDialogButtonBox::Ok);
    m_export->setText(tr("E&xport"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(m_form);
    layout->addWidget(m_warning);
    layout->addStretch(1);
    layout->addWidget(buttons);
    setMinimumWidth(560);

    connect(m_subject, &QComboBox::currentIndexChanged, this, [this] {
        updateFormats();
        updateOptions();
        if (const int i = subject(); i >= 0 && !m_subjects[i].baseName.isEmpty()) {
            const QString dir = QFileInfo(m_path->text()).path();
            m_path->setText(QDir(dir).filePath(m_subjects[i].baseName));
            followFormat();
        }
        updateState();
    });
    connect(m_format, &QComboBox::currentIndexChanged, this, [this] {
        updateOptions();
        followFormat();
        updateState();
    });
    connect(m_surface, &QComboBox::currentIndexChanged, this, &ExportDialog::updateState);
    connect(m_path, &QLineEdit::editingFinished, this, &ExportDialog::followPath);
    connect(m_path, &QLineEdit::textChanged, this, &ExportDialog::updateState);
    connect(m_browse, &QPushButton::clicked, this, &ExportDialog::browse);

    // The first subject that can be exported, named after itself in `directory`.
    int first = 0;
    while (first < m_subjects.size() && !m_subjects[first].unavailable.isEmpty())
        ++first;
    m_subject->blockSignals(true);
    m_subject->setCurrentIndex(first < m_subjects.size() ? first : 0);
    m_subject->blockSignals(false);
    const QString base = subject() >= 0 && !m_subjects[subject()].baseName.isEmpty()
                             ? m_subjects[subject()].baseName
                             : QStringLiteral("export");
    m_path->setText(QDir(directory.isEmpty() ? QDir::currentPath() : directory).filePath(base));
    updateFormats();
    updateOptions();
    followFormat();
    updateState();
}

int ExportDialog::subject() const
{
    const int i = m_subject->currentIndex();
    return i >= 0 && i < m_subjects.size() && m_subjects[i].unavailable.isEmpty() ? i : -1;
}

void ExportDialog::setSubject(int index)
{
    m_subject->setCurrentIndex(index);
}

const FileFormat *ExportDialog::format() const
{
    const int i = m_format->currentIndex();
    if (subject() < 0 || i < 0 || !entryEnabled(m_format, i))
        return nullptr;
    return findFormat("x" + m_format->itemData(i).toString().toStdString());
}

bool ExportDialog::setFormat(const QString &extension)
{
    const int i = m_format->findData(extension.toLower());
    if (i < 0 || !entryEnabled(m_format, i))
        return false;
    m_format->setCurrentIndex(i);
    return true;
}

ExportOptions ExportDialog::options() const
{
    ExportOptions o;
    o.gmsh.version = GmshWriteOptions::Version(m_mshVersion->currentData().toInt());
    o.gmsh.saveAll = m_saveAll->isChecked();
    const FileFormat *f = format();
    if (f != nullptr && f->options.surface && m_surface->currentIndex() >= 0)
        o.surface = m_surface->currentData().toInt();
    return o;
}

QString ExportDialog::path() const
{
    const FileFormat *f = format();
    return f ? withExtension(m_path->text().trimmed(), QString::fromUtf8(f->extension))
             : m_path->text().trimmed();
}

void ExportDialog::setPath(const QString &path)
{
    m_path->setText(path);
    followPath();
}

QString ExportDialog::warning() const
{
    return m_warning->text();
}

QString ExportDialog::refusal(const FileFormat &format, ExportData data)
{
    switch (exportFit(format, data)) {
    case ExportFit::Fits:
        return {};
    case ExportFit::NeedsCells:
        return tr("This format holds tetrahedra; a surface model has none");
    case ExportFit::DropsCells:
        return tr("This format holds no volume cells");
    case ExportFit::DropsPyramidsPrisms:
        return tr("This format holds tetrahedra only; this mesh has pyramids and prisms");
    }
    return {};
}

QString ExportDialog::lossSentence(const FileFormat &format, ExportData data, int surfaceCount)
{
    QStringList words;
    for (const FormatLoss loss : formatLosses(format, data)) {
        switch (loss) {
        case FormatLoss::OtherSurfaces:
            if (data != ExportData::SurfaceModel || surfaceCount > 1)
                words << tr("every surface but the chosen one");
            break;
        case FormatLoss::SurfaceNames:
            words << tr("surface names");
            break;
        case FormatLoss::FeatureTypes:
            words << tr("feature types (horizon, fault…)");
            break;
        case FormatLoss::Regions:
            words << tr("regions");
            break;
        case FormatLoss::LinesAndCorners:
            words << tr("contact lines and corners");
            break;
        case FormatLoss::VolumeCells:
            words << tr("volume cells");
            break;
        case FormatLoss::PyramidsPrisms:
            words << tr("pyramids and prisms");
            break;
        case FormatLoss::DoublePrecision:
            words << tr("double precision (coordinates stored as 32-bit floats)");
            break;
        }
    }
    if (words.isEmpty())
        return {};
    return tr("%1 does not keep: %2.")
        .arg(QString::fromUtf8(format.name), words.join(QStringLiteral(", ")));
}

// Every writer is listed; those that cannot take the subject are disabled and say why.
void ExportDialog::updateFormats()
{
    const int s = subject();
    const ExportData data = s >= 0 ? m_subjects[s].data : ExportData::SurfaceModel;
    m_format->blockSignals(true);
    for (int i = 0; i < m_format->count(); ++i) {
        const FileFormat *f = findFormat("x" + m_format->itemData(i).toString().toStdString());
        const QString why = s < 0 || f == nullptr ? QString() : refusal(*f, data);
        setEntryEnabled(m_format, i, s >= 0 && why.isEmpty(), why);
    }
    int current = m_format->currentIndex();
    if (current < 0 || !entryEnabled(m_format, current)) {
        current = -1;
        for (int i = 0; i < m_format->count() && current < 0; ++i)
            if (entryEnabled(m_format, i))
                current = i;
        m_format->setCurrentIndex(current);
    }
    m_format->blockSignals(false);
}

void ExportDialog::updateOptions()
{
    const FileFormat *f = format();
    const int s = subject();
    const bool gmsh = f != nullptr && f->options.gmsh;
    const bool surface = f != nullptr && f->options.surface && s >= 0
                         && m_subjects[s].data == ExportData::SurfaceModel;
    m_form->setRowVisible(m_mshVersion, gmsh);
    m_form->setRowVisible(m_saveAll, gmsh);
    m_form->setRowVisible(m_surface, surface);
    m_surface->blockSignals(true);
    m_surface->clear();
    if (surface) {
        if (f->options.allSurfaces)
            m_surface->addItem(tr("All surfaces"), -1);
        const QStringList &names = m_subjects[s].surfaceNames;
        for (int i = 0; i < names.size(); ++i)
            m_surface->addItem(names[i].isEmpty() ? tr("Surface %1").arg(i) : names[i], i);
    }
    m_surface->blockSignals(false);
}

void ExportDialog::followFormat()
{
    if (const FileFormat *f = format())
        m_path->setText(withExtension(m_path->text(), QString::fromUtf8(f->extension)));
}

// A typed extension of another format that fits chooses it; any other gets the format's own.
void ExportDialog::followPath()
{
    const QString typed = QString::fromStdString(fileExtension(m_path->text().toStdString()));
    const FileFormat *f = format();
    if (!typed.isEmpty() && (f == nullptr || typed != QString::fromUtf8(f->extension))
        && setFormat(typed))
        return; // the format's change has followed
    followFormat();
    updateState();
}

void ExportDialog::browse()
{
    const FileFormat *f = format();
    if (f == nullptr)
        return;
    const QString filter =
        tr("%1 (*%2)").arg(QString::fromUtf8(f->name), f->extension) + ";;" + tr("All files (*)");
    const QString chosen = QFileDialog::getSaveFileName(
        this, tr("Export To"), m_path->text(), filter, nullptr, QFileDialog::DontConfirmOverwrite);
    if (!chosen.isEmpty())
        setPath(withExtension(chosen, QString::fromUtf8(f->extension)));
}

void ExportDialog::updateState()
{
    const int s = subject();
    const FileFormat *f = format();
    QString text;
    if (s >= 0 && f != nullptr) {
        const ExportSubject &subject = m_subjects[s];
        text = lossSentence(*f, subject.data, int(subject.surfaceNames.size()));
    } else if (s < 0) {
        text = tr("Nothing can be exported yet: open a model first.");
    }
    m_warning->setText(text);
    m_warning->setVisible(!text.isEmpty());
    m_export->setEnabled(s >= 0 && f != nullptr && !m_path->text().trimmed().isEmpty());
}

} // namespace stratamesh
