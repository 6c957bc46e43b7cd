// The report of one remeshing, as stratamesh-cli remesh writes it and the GUI's project files keep
// it beside each run's output model: one builder for both, so that a run saved from the window
// reads like one made on the command line.
#pragma once

#include "model/model.h"
#include "model/validity.h"
#include "quality/model_comparison.h"
#include "remesh/simplification_ledger.h"
#include "remesh/surface_remesher.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace stratamesh {

// What a remeshing reports beyond its models, ledger and comparison.
struct RemeshReportFacts {
    int initialSiteCount = 0;
    int siteCount = 0;
    int refinementRounds = 0;    // up to the round kept
    int refinementRoundsRun = 0; // all the rounds run
    int remainingTargets = 0;
    RemeshTimings timings;
    std::vector<double> energy;
    int sizedSiteCount = 0;        // the sites of the feature sizing field (0: not known)
    double smallestCellSize = 0.0; // its smallest size (0: not known)
    int pocketsOpened = 0;         // closed pockets re-triangulated open (pocket_repair.h)
};

struct RemeshReportParts {
    QString file;       // the input model's file
    QString outputFile; // the output model's file
    const Model *input = nullptr;
    const Model *output = nullptr;
    const RemeshParams *params = nullptr;
    const SimplificationLedger *ledger = nullptr;
    const ModelComparison *comparison = nullptr;
    // nullptr: not checked (the GUI showed it when the model was opened); the side has no
    // `validity` then.
    const ValidityReport *inputValidity = nullptr;
    const ValidityReport *outputValidity = nullptr;
    RemeshReportFacts facts;
};

// file, output_file, topology_edits, ledger_balance, refinement, parameters, input, output,
// hausdorff_pct_bbox, hausdorff, histograms, timings, ledger, energy.
QJsonObject remeshReportJson(const RemeshReportParts &parts);

} // namespace stratamesh
