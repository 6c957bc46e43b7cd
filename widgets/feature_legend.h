// A small translucent legend drawn over the 3D view: feature types with their colours, and the
// features themselves when there are few enough to read.
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
    std::vector<Row> rows() const;
    void relayout();

    std::vector<LegendEntry> m_entries;
    bool m_boxVisible = false;
};

} // namespace stratamesh
