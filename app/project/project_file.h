// A StrataMesh project (NAME.smproj): the input model's path relative to the project file, every
// remesh run with its complete parameters, its figures, its review decisions, and which run is
// shown. The runs' results live beside it in NAME_runs/run-001/… (project_runs.h); the .smproj is
// JSON with a schema number so that a newer file is refused rather than misread.
#pragma once

#include "remesh/surface_remesher.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace stratamesh {

// 2: d_resolution's default is −1 (automatic) and 0 asks for no simplification.
inline constexpr int kProjectSchema = 2;

// The figures the Runs list and `stratamesh-cli project` show without opening the run folder.
struct ProjectRunFigures {
    int sites = 0; // final, with local refinement
    qint64 vertices = 0;
    qint64 triangles = 0;
    bool valid = false;
    double hausdorffPctBbox = 0.0;
    double meanQuality = 0.0;
    int ledgerRecords = 0;
};

struct ProjectRun {
    int id = 0;     // 1, 2, … in the order the runs were made
    QString folder; // "run-001", inside the runs folder
    RemeshParams params;
    ProjectRunFigures figures;
    QJsonObject review; // ReviewDecisions::toJson(): {"records": [...]}
};

struct ProjectFile {
    QString inputPath;          // absolute once read (stored relative to the project file)
    bool inputIsSample = false; // the bundled sample model, which has no file
    std::vector<ProjectRun> runs;
    int shownRun = -1; // index into runs, -1 for none
    QJsonObject view;  // optional view state (camera), kept as the GUI wrote it
};

// "NAME.smproj" -> "NAME_runs" beside it.
QString projectRunsFolder(const QString &projectPath);
QString runFolderName(int id);           // "run-001"
bool isProjectFile(const QString &path); // by the .smproj extension

QJsonObject projectToJson(const ProjectFile &project, const QString &projectPath);
// FileError naming `projectPath`: a newer schema (both numbers named), a missing or wrong value.
ProjectFile projectFromJson(const QJsonObject &json, const QString &projectPath);
// FileError: the file cannot be read, is not JSON (the parser's cause and offset), or as above.
ProjectFile readProjectFile(const QString &projectPath);

// Records accepted or flagged in a ReviewDecisions JSON object.
int reviewedCount(const QJsonObject &review);

} // namespace stratamesh
