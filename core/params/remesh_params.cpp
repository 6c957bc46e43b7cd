// The remesh parameters (thesis ch. 4): one entry each; the defaults are RemeshParams'.
#include "common/translate_noop.h"
#include "params/param_tables.h"

namespace stratamesh {

namespace {

ParamTable<RemeshParams> makeTable()
{
    using P = RemeshParams;
    ParamTable<P> t("remesh");
    ParamInfo i;

    i = {};
    i.key = "sites", i.flag = "--sites", i.jsonKey = "sites", i.type = ParamType::Int;
    i.minimum = kMinRemeshSites, i.maximum = kMaxRemeshSites, i.zeroMeansOff = true;
    i.valueName = "N", i.thesis = "Alg. 4.1";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Number of &sites:");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Sites spread over all the surfaces; each becomes about one vertex. At least one per "
        "surface; 0: from the edge length.");
    t.add(memberParam(&P::sites, i));

    i = {};
    i.key = "edge_length", i.flag = "--edge-length", i.jsonKey = "edge_length";
    i.minimum = 0.0, i.maximum = 1e300, i.unit = "m", i.valueName = "L";
    i.scale = ParamScale::Length;
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Target &edge length:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "The number of sites is derived from the total area for this edge "
                               "length (hexagonal packing); 0: from the number of sites.");
    t.add(memberParam(&P::edgeLength, i));

    i = {};
    i.key = "d_resolution", i.flag = "--d-resolution", i.jsonKey = "d_resolution";
    i.minimum = kAutoDResolution, i.maximum = 1e300, i.unit = "m", i.valueName = "D";
    i.scale = ParamScale::Length, i.thesis = "Alg. 4.2, step 4";
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "Auto");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&d_resolution:");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Features smaller than this may be simplified: parts closer than it are merged, thin "
        "strips narrower than it and the strip factor are removed; 0 simplifies nothing and "
        "pins sites on close features. -1 (Auto): nothing merged, thin strips removed by the strip "
        "factor alone. At most a tenth of the bounding-box diagonal.");
    t.add(memberParam(&P::dResolution, i));

    i = {};
    i.key = "strip_factor", i.flag = "--strip-factor", i.jsonKey = "strip_factor";
    i.minimum = 0.0, i.maximum = 1.0, i.valueName = "F";
    i.unit = QT_TRANSLATE_NOOP("stratamesh::Params", "× edge length");
    i.decimals = 2;
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "Off");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Remove thin s&trips under:");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Surfaces narrower than this between two long lines (a small fault throw) are removed "
        "whole before remeshing, their two lines merged into one; 0 keeps them.");
    t.add(memberParam(&P::stripWidthFactor, i));

    i = {};
    i.key = "lfs_factor", i.flag = "--lfs-factor", i.jsonKey = "lfs_factor";
    i.minimum = 0.0, i.maximum = 4.0, i.valueName = "K", i.decimals = 2;
    i.unit = QT_TRANSLATE_NOOP("stratamesh::Params", "× feature distance");
    i.thesis = "§4.6.2";
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "Off");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Cells near c&lose features:");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Near two features that do not meet (the two lines of a small fault throw, close "
        "corners), cells are at most this times their distance, so that both are kept without "
        "needles; the sites grow accordingly, to at most 4 times those asked. Use it with the "
        "strip factor at 0 to keep small throws rather than remove them; 0 turns it off.");
    t.add(memberParam(&P::lfsFactor, i));

    i = {};
    i.key = "iterations", i.flag = "--iterations", i.jsonKey = "iterations";
    i.type = ParamType::Int, i.minimum = 0, i.maximum = 100000, i.valueName = "N";
    i.thesis = "§4.3 (100)";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Iterations:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Iterations of the centroidal Voronoi optimisation of the sites.");
    t.add(memberParam(&P::iterations, i));

    i = seedParamInfo(
        2147483647, QT_TRANSLATE_NOOP(
                        "stratamesh::Params",
                        "Seed of the initial random sampling: the same seed gives the same mesh."));
    t.add(memberParam(&P::seed, i));

    i = {};
    i.key = "refinement_rounds", i.flag = "--refinement-rounds", i.jsonKey = "refinement_rounds";
    i.type = ParamType::Int, i.minimum = 0, i.maximum = 100, i.valueName = "R";
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "Off");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Re&finement rounds:");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Rounds of more sites where the result is not valid or its topology differs from the "
        "input's (4 more while it is not valid); 0 turns refinement off.");
    t.add(memberParam(&P::refinementRounds, i));

    i = {};
    i.key = "pin_features", i.flag = "--pin-features", i.jsonKey = "pin_features";
    i.type = ParamType::Flag;
    i.thesis = "§4.6.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Pin sites on close features");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Refinement rounds put sites on the corners and lines around each topology change, as "
        "close as the nearest other feature, and grade the surfaces around them: more features "
        "are kept, with up to 4 times the sites asked plus the sites pinned on the features (9 "
        "times in all on an 8-fault network at 1000 sites), and more triangles under 30°. Always "
        "on when d_resolution is 0.");
    t.add(memberParam(&P::refinementPinsFeatures, i));

    i = {};
    i.key = "adaptive", i.flag = "--adaptive", i.jsonKey = "adaptive", i.type = ParamType::Flag;
    i.thesis = "Fig. 4.19";
    i.label =
        QT_TRANSLATE_NOOP("stratamesh::Params", "&Adaptive density (more sites near corners)");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Site density grows near corners, so small features keep more triangles.");
    t.add(memberParam(&P::adaptive, i));

    i = {};
    i.key = "merge_all", i.flag = "--merge-all", i.jsonKey = "merge_all", i.type = ParamType::Flag;
    i.thesis = "Alg. 4.2, step 3";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Merge all extra points of a cell");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "A cell part with more than two points has them all merged, as in the thesis; without "
        "it, only the closest until two are left, which keeps more of the model.");
    t.add(memberParam(&P::mergeAllExtraPoints, i));
    return t;
}

} // namespace

const ParamTable<RemeshParams> &remeshParamTable()
{
    static const ParamTable<RemeshParams> table = makeTable();
    return table;
}

} // namespace stratamesh
