#include "study_window.h"

#include "error_message.h"
#include "study_file.h"
#include "task_result.h"
#include "task_result_window.h"

#include "common/error.h"
#include "io/model_reader.h"
#include "model/topology.h"

#include <QApplication>
#include <QChartView>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QMessageBox>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <QValueAxis>

#include <limits>
#include <map>

namespace stratamesh {

namespace {

// Numbers are stored as numbers, so that sorting a column of sites sorts 300 before 1000.
QStandardItem *itemFor(const QJsonValue &value)
{
    auto *item = new QStandardItem;
    if (value.isDouble())
        item->setData(value.toDouble(), Qt::DisplayRole);
    else if (value.isBool())
        item->setData(value.toBool() ? QStringLiteral("true") : QStringLiteral("false"),
                      Qt::DisplayRole);
    else
        item->setData(value.toString(), Qt::DisplayRole);
    item->setEditable(false);
    return item;
}

QChart *lineChart(const QString &title, const QString &xTitle, const QString &yTitle,
                  const std::map<QString, std::vector<QPointF>> &series)
{
    auto *chart = new QChart;
    chart->setTitle(title);
    auto *x = new QValueAxis;
    auto *y = new QValueAxis;
    x->setTitleText(xTitle);
    y->setTitleText(yTitle);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    double hi[2] = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
    for (const auto &[name, points] : series) {
        auto *line = new QLineSeries;
        line->setName(name);
        line->setPointsVisible(true);
        std::vector<QPointF> sorted = points;
        std::sort(sorted.begin(), sorted.end(),
                  [](const QPointF &a, const QPointF &b) { return a.x() < b.x(); });
        for (const QPointF &p : sorted) {
            line->append(p);
            lo[0] = std::min(lo[0], p.x()), hi[0] = std::max(hi[0], p.x());
            lo[1] = std::min(lo[1], p.y()), hi[1] = std::max(hi[1], p.y());
        }
        chart->addSeries(line);
        line->attachAxis(x);
        line->attachAxis(y);
    }
    if (lo[0] <= hi[0]) {
        const double padX = std::max(1e-9, 0.05 * (hi[0] - lo[0]));
        const double padY = std::max(1e-9, 0.05 * (hi[1] - lo[1]));
        x->setRange(lo[0] - padX, hi[0] + padX);
        y->setRange(lo[1] - padY, hi[1] + padY);
    }
    return chart;
}

} // namespace

StudyWindow::StudyWindow(QWidget *parent)
    : QMainWindow(parent), m_model(new QStandardItemModel(this)),
      m_proxy(new QSortFilterProxyModel(this)), m_filter(new QLineEdit), m_summary(new QLabel),
      m_table(new QTableView), m_charts(new QTabWidget), m_qualityChart(new QChartView),
      m_countChart(new QChartView)
{
    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterKeyColumn(-1); // every column
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setSortRole(Qt::DisplayRole);
    m_table->setModel(m_proxy);
    m_table->setSortingEnabled(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_filter->setClearButtonEnabled(true);
    connect(m_filter, &QLineEdit::textChanged, m_proxy,
            &QSortFilterProxyModel::setFilterFixedString);
    connect(m_table, &QTableView::doubleClicked, this,
            [this](const QModelIndex &index) { openTaskAtRow(index.row()); });
    m_qualityChart->setRenderHint(QPainter::Antialiasing);
    m_countChart->setRenderHint(QPainter::Antialiasing);
    m_charts->addTab(m_qualityChart, QString());
    m_charts->addTab(m_countChart, QString());

    auto *top = new QWidget;
    auto *topLayout = new QVBoxLayout(top);
    topLayout->setContentsMargins(4, 4, 4, 4);
    topLayout->addWidget(m_filter);
    topLayout->addWidget(m_table);
    topLayout->addWidget(m_summary);
    auto *split = new QSplitter(Qt::Vertical);
    split->addWidget(top);
    split->addWidget(m_charts);
    setCentralWidget(split);
    resize(1100, 800);
    retranslate();
}

StudyWindow::~StudyWindow() = default;

void StudyWindow::openStudy(const QString &path)
{
    QString table = path;
    if (QFileInfo(path).suffix().compare(QLatin1String("smstudy"), Qt::CaseInsensitive) == 0)
        table = study::readStudy(path, {}).outputDir + QStringLiteral("/study.json");
    QFile file(table);
    if (!file.open(QIODevice::ReadOnly))
        throw FileError(table.toStdString(), 0,
                        "no gathered table (run stratamesh-cli study STUDY --gather): "
                            + file.errorString().toStdString());
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject()
        || !doc.object().value(QStringLiteral("rows")).isArray())
        throw FileError(table.toStdString(), 0, "not a gathered study table");
    m_tablePath = QFileInfo(table).absoluteFilePath();
    m_study = doc.object();

    QStringList columns;
    for (const QJsonValue &c : m_study.value(QStringLiteral("columns")).toArray())
        columns << c.toString();
    m_model->clear();
    m_model->setHorizontalHeaderLabels(columns);
    for (const QJsonValue &r : m_study.value(QStringLiteral("rows")).toArray()) {
        QList<QStandardItem *> items;
        for (const QString &c : columns)
            items << itemFor(r.toObject().value(c));
        items.front()->setData(r.toObject(), Qt::UserRole); // the whole row, for a double-click
        m_model->appendRow(items);
    }
    m_table->sortByColumn(-1, Qt::AscendingOrder);
    fillCharts();
    retranslate();
}

void StudyWindow::fillCharts()
{
    const QJsonArray rows = m_study.value(QStringLiteral("rows")).toArray();
    QString xKey = QStringLiteral("remesh.sites");
    bool haveX = false;
    for (const QJsonValue &r : rows)
        haveX = haveX || r.toObject().contains(xKey);
    if (!haveX)
        xKey = QStringLiteral("task");
    std::map<QString, std::vector<QPointF>> quality, triangles;
    for (const QJsonValue &v : rows) {
        const QJsonObject r = v.toObject();
        if (r.value(QStringLiteral("status")).toString() != QLatin1String("ok"))
            continue;
        const QString model = r.value(QStringLiteral("model")).toString();
        const double x = r.value(xKey).toDouble();
        if (r.contains(QStringLiteral("mean_quality")))
            quality[model].emplace_back(x, r.value(QStringLiteral("mean_quality")).toDouble());
        if (r.contains(QStringLiteral("triangles")))
            triangles[model].emplace_back(x, r.value(QStringLiteral("triangles")).toDouble());
    }
    const QString xTitle = xKey == QLatin1String("task") ? tr("Task") : tr("Sites asked");
    m_qualityChart->setChart(lineChart(tr("Mean triangle quality Q against the resolution"), xTitle,
                                       tr("Mean Q"), quality));
    m_countChart->setChart(lineChart(tr("Output triangles against the resolution"), xTitle,
                                     tr("Triangles"), triangles));
}

void StudyWindow::openTaskAtRow(int row)
{
    const QModelIndex index = m_proxy->mapToSource(m_proxy->index(row, 0));
    if (!index.isValid())
        return;
    const QJsonObject r = m_model->item(index.row(), 0)->data(Qt::UserRole).toJsonObject();
    try {
        const study::TaskResult task = study::readTaskResult(m_tablePath, r);
        QApplication::setOverrideCursor(Qt::WaitCursor);
        auto input =
            std::make_shared<const Model>(recoverTopology(readModel(task.input.toStdString())));
        std::shared_ptr<const Model> output;
        if (!task.output.isEmpty())
            output = std::make_shared<const Model>(
                recoverTopology(readModel(task.output.toStdString())));
        QApplication::restoreOverrideCursor();
        if (!m_taskWindow)
            m_taskWindow = new TaskResultWindow(this);
        m_taskWindow->show(tr("Task %1 — %2: input (left), remesh (right)")
                               .arg(task.id)
                               .arg(r.value(QStringLiteral("model")).toString()),
                           std::move(input), std::move(output), task.ledger);
    } catch (const std::exception &e) {
        QApplication::restoreOverrideCursor();
        const Message m = errorMessage(e);
        QMessageBox::warning(this, tr("Cannot open the task"), m.text);
    }
}

void StudyWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void StudyWindow::retranslate()
{
    setWindowTitle(m_tablePath.isEmpty()
                       ? tr("Study")
                       : tr("Study %1").arg(m_study.value(QStringLiteral("name")).toString()));
    m_filter->setPlaceholderText(tr("Filter the rows (model, status, error…)"));
    m_charts->setTabText(0, tr("Quality"));
    m_charts->setTabText(1, tr("Element counts"));
    const QJsonArray rows = m_study.value(QStringLiteral("rows")).toArray();
    int ok = 0;
    for (const QJsonValue &r : rows)
        ok += r.toObject().value(QStringLiteral("status")).toString() == QLatin1String("ok");
    m_summary->setText(tr("%n task(s), %1 ok; double-click a row to see its input and output",
                          nullptr, int(rows.size()))
                           .arg(ok));
    if (!m_tablePath.isEmpty())
        fillCharts();
}

} // namespace stratamesh
