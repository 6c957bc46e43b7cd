#include "feature_legend.h"

#include <QEvent>
#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

namespace stratamesh {

namespace {
constexpr int kMargin = 10; // from the parent's corner
constexpr int kPadding = 8; // inside the frame
constexpr int kSwatch = 12;
constexpr int kIndent = 16;
} // namespace

FeatureLegend::FeatureLegend(QWidget *parent) : QWidget(parent)
{
    setAttribute(Qt::WA_TransparentForMouseEvents); // the view below keeps every mouse gesture
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    if (parent)
        parent->installEventFilter(this);
    hide();
}

QString FeatureLegend::typeLabel(FeatureType type)
{
    switch (type) {
    case FeatureType::Horizon:
        return tr("Horizons");
    case FeatureType::Fault:
        return tr("Faults");
    case FeatureType::Unconformity:
        return tr("Unconformities");
    case FeatureType::Boundary:
        return tr("Box");
    case FeatureType::Unknown:
        break;
    }
    return tr("Other surfaces");
}

void FeatureLegend::setEntries(const std::vector<LegendEntry> &entries, bool boxVisible)
{
    m_entries = entries;
    m_boxVisible = boxVisible;
    setVisible(!m_entries.empty());
    relayout();
    update();
}

std::vector<FeatureLegend::Row> FeatureLegend::rows(Detail detail) const
{
    int features = 0;
    for (const LegendEntry &e : m_entries)
        features += e.type == FeatureType::Boundary ? 0 : e.featureCount;
    const bool listFeatures = detail == Detail::Full && features <= kMaxListedFeatures;

    std::vector<Row> result;
    for (const LegendEntry &e : m_entries) {
        Row header;
        header.color = e.color;
        header.header = true;
        if (detail == Detail::Names) {
            header.text = typeLabel(e.type);
            header.dimmed = e.type == FeatureType::Boundary && !m_boxVisible;
            result.push_back(header);
            continue;
        }
        if (e.type == FeatureType::Boundary) {
            header.text =
                m_boxVisible
                    ? tr("%1 (%n surface(s))", nullptr, e.surfaceCount).arg(typeLabel(e.type))
                    : tr("%1 (hidden)").arg(typeLabel(e.type));
            header.dimmed = !m_boxVisible;
            result.push_back(header);
            continue;
        }
        header.text = tr("%1 (%n surface(s))", nullptr, e.surfaceCount).arg(typeLabel(e.type));
        result.push_back(header);
        if (!listFeatures)
            continue;
        for (int i = 0; i < e.featureNames.size(); ++i) {
            Row row;
            row.color =
                std::size_t(i) < e.featureColors.size() ? e.featureColors[std::size_t(i)] : e.color;
            row.text = e.featureNames[i].isEmpty() ? tr("(unnamed)") : e.featureNames[i];
            result.push_back(row);
        }
    }
    return result;
}

QSize FeatureLegend::sizeFor(Detail detail) const
{
    QFont bold = font();
    bold.setBold(true);
    const QFontMetrics normal(font()), strong(bold);
    const int lineHeight = qMax(strong.height(), kSwatch) + 3;
    const bool title = detail == Detail::Full;
    int width = title ? strong.horizontalAdvance(tr("Legend")) : 0;
    const auto all = rows(detail);
    for (const Row &row : all) {
        const int text = (row.header ? strong : normal).horizontalAdvance(row.text);
        width = qMax(width, (row.header ? 0 : kIndent) + kSwatch + 6 + text);
    }
    return {width + 2 * kPadding, int(all.size() + (title ? 1 : 0)) * lineHeight + 2 * kPadding};
}

QSize FeatureLegend::sizeHint() const
{
    return sizeFor(m_detail);
}

void FeatureLegend::relayout()
{
    m_detail = Detail::Names;
    if (const QWidget *view = parentWidget()) {
        const double maxWidth = kMaxWidthShare * view->width();
        const double maxHeight = kMaxHeightShare * view->height();
        for (Detail d : {Detail::Full, Detail::Types}) {
            const QSize size = sizeFor(d);
            if (size.width() <= maxWidth && size.height() <= maxHeight) {
                m_detail = d;
                break;
            }
        }
    } else {
        m_detail = Detail::Full;
    }
    resize(sizeHint());
    move(kMargin, kMargin);
    raise();
    update();
}

bool FeatureLegend::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == parent() && event->type() == QEvent::Resize)
        relayout();
    return QWidget::eventFilter(watched, event);
}

void FeatureLegend::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange || event->type() == QEvent::FontChange)
        relayout();
    QWidget::changeEvent(event);
}

void FeatureLegend::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    QPainterPath frame;
    frame.addRoundedRect(QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5), 6, 6);
    painter.fillPath(frame, QColor(255, 255, 255, 215));
    painter.setPen(QColor(0, 0, 0, 60));
    painter.drawPath(frame);

    QFont bold = font();
    bold.setBold(true);
    const QFontMetrics strong(bold);
    const int lineHeight = qMax(strong.height(), kSwatch) + 3;
    int y = kPadding;
    if (m_detail == Detail::Full) {
        painter.setFont(bold);
        painter.setPen(QColor(30, 34, 40));
        painter.drawText(QRect(kPadding, y, width() - 2 * kPadding, lineHeight),
                         Qt::AlignVCenter | Qt::AlignLeft, tr("Legend"));
        y += lineHeight;
    }
    for (const Row &row : rows(m_detail)) {
        const int x = kPadding + (row.header ? 0 : kIndent);
        const QRect swatch(x, y + (lineHeight - kSwatch) / 2, kSwatch, kSwatch);
        QColor fill = row.color;
        if (row.dimmed)
            fill.setAlpha(90);
        painter.setPen(QColor(0, 0, 0, row.dimmed ? 50 : 110));
        painter.setBrush(fill);
        painter.drawRoundedRect(swatch, 2, 2);
        painter.setFont(row.header ? bold : font());
        painter.setPen(row.dimmed ? QColor(110, 115, 122) : QColor(30, 34, 40));
        painter.drawText(
            QRect(x + kSwatch + 6, y, width() - x - kSwatch - 6 - kPadding, lineHeight),
            Qt::AlignVCenter | Qt::AlignLeft, row.text);
        y += lineHeight;
    }
}

} // namespace stratamesh
