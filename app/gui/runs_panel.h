// The Runs dock's table: one row per remesh run of the session or project (its parameters, sizes,
// validity, Hausdorff, mean Q, review progress), the shown run marked; choosing a row asks for
// that run to be shown (ProjectWorkflow makes it an undoable command). Compare… asks for two runs
// side by side, the first in the input view; Input vs Output goes back to the input model.
#pragma once

#include <QWidget>

#include <vector>

class QPushButton;
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

    // `compared`: the run in the input view (-1: the input model is there).
    void setRuns(const std::vector<RunsRow> &rows, int shown, int compared = -1);
    QTableWidget *table() const { return m_table; }
    QPushButton *compareButton() const { return m_compare; }
    QPushButton *inputButton() const { return m_input; }
    void retranslate();

signals:
    // The user chose this row (not emitted by setRuns).
    void runChosen(int index);
    // Run `first` in the input view, `second` in the output view.
    void compareChosen(int first, int second);
    void inputChosen();

private:
    void chooseComparison();

    QTableWidget *m_table;
    QPushButton *m_compare;
    QPushButton *m_input;
    std::vector<QString> m_names; // "Run 2: 300 sites, 20 iterations", for the Compare dialog
    int m_shown = -1;
    int m_compared = -1;
};

} // namespace stratamesh
