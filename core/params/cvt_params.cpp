// The CVT parameters the `cvt` command exposes (thesis §4.3); the defaults are CvtParams'.
#include "common/translate_noop.h"
#include "params/param_tables.h"

namespace stratamesh {

namespace {

ParamTable<CvtParams> makeTable()
{
    using P = CvtParams;
    ParamTable<P> t("cvt");
    ParamInfo i;

    i = {};
    i.key = "iterations", i.flag = "--iterations", i.jsonKey = "iterations";
    i.type = ParamType::Int, i.minimum = 0, i.maximum = 1000000, i.valueName = "N";
    i.thesis = "§4.3";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Iterations:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Iterations of the centroidal Voronoi optimisation of the sites.");
    t.add(memberParam(&P::iterations, i));

    i = {};
    i.key = "alpha", i.flag = "--alpha", i.jsonKey = "alpha", i.minimum = 0.0, i.maximum = 1.0;
    i.valueName = "A", i.decimals = 2, i.thesis = "§4.3.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Boundary &weight α:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Weight of the boundary energy in F = (1 − α) F_CVT + α F_B.");
    t.add(memberParam(&P::alpha, i));

    i = {};
    i.key = "lloyd", i.flag = "--lloyd", i.jsonKey = "lloyd", i.type = ParamType::Flag;
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Lloyd iterations");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Lloyd iterations instead of L-BFGS (the CVT energy alone: no "
                               "boundary weight).");
    t.add(memberParam(&P::lloyd, i));
    return t;
}

} // namespace

const ParamTable<CvtParams> &cvtParamTable()
{
    static const ParamTable<CvtParams> table = makeTable();
    return table;
}

} // namespace stratamesh
