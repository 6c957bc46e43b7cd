// File > Open Study…: the gathered table of a study (sortable, filterable), quality and element
// counts against the resolution per model, and a double-click opening a task's input and output
// side by side with its ledger. It reads what `stratamesh-cli study --gather` wrote; nothing is
// recomputed here.
#pragma once

#include <QJsonObject>
#include <QMainWindow>

class QChartView;
class QLabel;
class QLineEdit;
class QSortFilterProxyModel;
class QStandardItemModel;
class QTabWidget;
class QTableView;

namespace stratamesh {

class TaskResultWindow;

class StudyWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit StudyWindow(QWidget *parent = nullptr);
    ~StudyWindow() override;

    // A gathered study.json, or a .smstudy whose output holds one. Throws FileError.
    void openStudy(const QString &path);
    // Opens the task of the given (filtered, sorted) table row, as a double-click does.
    void openTaskAtRow(int row);

    QTableView *table() const { return m_table; }
    QLineEdit *filterEdit() const { return m_filter; }
    QChartView *qualityChart() const { return m_qualityChart; }
    QChartView *countChart() const { return m_countChart; }
    TaskResultWindow *taskWindow() const { return m_taskWindow; }
    const QString &tablePath() const { return m_tablePath; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fillCharts();

    QString m_tablePath;
    QJsonObject m_study;
    QStandardItemModel *m_model;
    QSortFilterProxyModel *m_proxy;
    QLineEdit *m_filter;
    QLabel *m_summary;
    QTableView *m_table;
    QTabWidget *m_charts;
    QChartView *m_qualityChart;
    QChartView *m_countChart;
    TaskResultWindow *m_taskWindow = nullptr;
};

} // namespace stratamesh
