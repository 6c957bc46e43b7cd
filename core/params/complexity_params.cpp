// The complexity parameters (thesis ch. 3): one entry each; the defaults are ComplexityParams'.
#include "common/translate_noop.h"
#include "params/param_tables.h"

namespace stratamesh {

namespace {

ParamTable<ComplexityParams> makeTable()
{
    using P = ComplexityParams;
    ParamTable<P> t("complexity");
    ParamInfo i;

    i = {};
    i.key = "h", i.flag = "--h", i.jsonKey = "h", i.minimum = 0.001, i.maximum = 1e12;
    i.unit = "m", i.valueName = "H", i.decimals = 3, i.thesis = "Table 3.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Characteristic size &h:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Elements smaller than h (h² for surfaces, h³ for regions) are "
                               "complex.");
    Param<P> h;
    h.info = i;
    h.get = [](const P &p) { return p.geometric.h; };
    h.set = [](P &p, double v) { p.geometric.h = v; };
    t.add(h);

    i = {};
    i.key = "alpha", i.flag = "--alpha", i.jsonKey = "alpha_deg", i.minimum = 0.1;
    i.maximum = 180.0, i.unit = "°", i.valueName = "A", i.decimals = 1, i.thesis = "Table 3.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Angle α:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Angles between elements smaller than α are complex.");
    Param<P> alpha;
    alpha.info = i;
    alpha.get = [](const P &p) { return p.geometric.alphaDegrees; };
    alpha.set = [](P &p, double v) { p.geometric.alphaDegrees = v; };
    t.add(alpha);

    i = {};
    i.key = "cells", i.flag = "--cells", i.jsonKey = "cells", i.type = ParamType::IntList;
    i.minimum = 1, i.maximum = kMaxComplexityCells, i.valueName = "N[,N...]";
    i.thesis = "Table 3.4";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Number of &cells:");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "Cells of the volumetric Voronoi diagram in which model elements are counted (the thesis "
        "uses 100, 1000 and 10000).");
    Param<P> cells;
    cells.info = i;
    cells.getList = [](const P &p) { return std::vector<double>(p.cells.begin(), p.cells.end()); };
    cells.setList = [](P &p, const std::vector<double> &v) {
        p.cells.assign(v.size(), 0);
        for (std::size_t k = 0; k < v.size(); ++k)
            p.cells[k] = static_cast<int>(v[k]);
    };
    t.add(cells);

    i = seedParamInfo(
        2147483647,
        QT_TRANSLATE_NOOP("stratamesh::Params",
                          "Seed of the initial random sites: the same seed gives the same "
                          "cells."));
    i.jsonString = true;
    t.add(memberParam(&P::seed, i));

    i = {};
    i.key = "iterations", i.flag = "--iterations", i.jsonKey = "iterations";
    i.type = ParamType::Int, i.minimum = 0, i.maximum = 10000, i.valueName = "N";
    i.thesis = "Fig. 3.7";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Lloyd iterations:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Lloyd iterations of the volumetric centroidal Voronoi "
                               "tessellation.");
    t.add(memberParam(&P::iterations, i));
    return t;
}

} // namespace

const ParamTable<ComplexityParams> &complexityParamTable()
{
    static const ParamTable<ComplexityParams> table = makeTable();
    return table;
}

} // namespace stratamesh
