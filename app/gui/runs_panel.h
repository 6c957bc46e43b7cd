// The Runs dock's table: one row per remesh run of the session or project (its parameters, sizes,
// validity, Hausdorff, mean Q, review progress), the shown run marked; choosing a row asks for
// that run to be shown (ProjectWorkflow makes it an undoable command).
#pragma once

#include <QWidget>

#include <vector>

class QTableWidget;

namespace stratamesh {

struct RunsRow {
    int id = 0;
    QString parameters; // "300 sites, 20 iterations"
    int sites = 0;
    qint64 vertices = 0;
    qint64 triangles = 0;
    bool valid = false;
    double hausdorffPctBbox = 0.0;
    double meanQuality = 0.0;
    int reviewed = 0;
    int records = 0;
};

class RunsPanel : public QWidget {
    Q_OBJECT
public:
    explicit RunsPanel(QWidget *parent = nullptr);

    void setRuns(const std::vector<RunsRow> &rows, int shown);
    QTableWidget *table() const { return m_table; }
    void retranslate();

signals:
    // The user chose this row (not emitted by setRuns).
    void runChosen(int index);

private:
    QTableWidget *m_table;
    int m_shown = -1;
};

} // namespace stratamesh
