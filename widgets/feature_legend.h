// A small translucent legend drawn over the 3D view: feature types with their colours, and the
// features themselves when there are few enough to read. It gives up detail as its view shrinks
// (two views side by side on a laptop screen), so that it never covers much of the model.
#pragma once

#include "model_scene.h"

#include <QWidget>

namespace stratamesh {

class FeatureLegend : public QWidget {
    Q_OBJECT
public:
    // Follows the top-left corner of its parent (normally the 3D view).
    explicit FeatureLegend(QWidget *parent);

    void setEntries(const std::vector<LegendEntry> &entries, bool boxVisible);
    const std::vector<LegendEntry> &entries() const { return m_entries; }
    // Shown under each type when the model has at most this many features in all.
    static constexpr int kMaxListedFeatures = 14;

    // What it shows, from most to least: title, types with counts and features; types with
    // counts; type names only. The first whose size fits the budget of the parent view.
    enum class Detail { Full, Types, Names };
    Detail detail() const { return m_detail; }
    // The share of its parent's width and height it may take before it gives up detail.
    static constexpr double kMaxWidthShare = 0.4;
    static constexpr double kMaxHeightShare = 0.35;

    static QString typeLabel(FeatureType type);
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Row {
        QColor color;
        QString text;
        bool header = false;
        bool dimmed = false;
    };
    std::vector<Row> rows(Detail detail) const;
    QSize sizeFor(Detail detail) const;
    void relayout();

    std::vector<LegendEntry> m_entries;
    bool m_boxVisible = false;
    Detail m_detail = Detail::Full;
};

} // namespace stratamesh
