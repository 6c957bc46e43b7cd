// The hybrid-mesh parameters (thesis ch. 5); the defaults are HybridParams'.
#include "common/translate_noop.h"
#include "params/param_tables.h"

namespace stratamesh {

namespace {

// An entry for a number held by a member of a member (the cells' or TetGen's parameters).
template <class Outer, class Inner>
Param<HybridParams> nestedParam(Outer HybridParams::*outer, double Inner::*field, ParamInfo info)
{
    Param<HybridParams> p;
    p.info = std::move(info);
    p.get = [outer, field](const HybridParams &params) { return (params.*outer).*field; };
    p.set = [outer, field](HybridParams &params, double v) { (params.*outer).*field = v; };
    return p;
}

ParamTable<HybridParams> makeTable()
{
    using P = HybridParams;
    ParamTable<P> t("hybrid");
    ParamInfo i;

    i = {};
    i.key = "sites", i.flag = "--sites", i.jsonKey = "sites", i.type = ParamType::Int;
    i.minimum = 4, i.maximum = 1000000, i.valueName = "N", i.thesis = "§5.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Number of volume &sites:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Sites of the volumetric centroidal Voronoi diagram of the model's "
                               "box; the surfaces are remeshed from them.");
    t.add(memberParam(&P::sites, i));

    i = {};
    i.key = "thin_ratio", i.flag = "--thin-ratio", i.jsonKey = "thin_ratio", i.minimum = 0.0;
    i.maximum = 1e6, i.valueName = "R", i.decimals = 2, i.thesis = "§5.3.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Thin-layer ratio:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "A cell between two surface triangles becomes a prism or a pyramid "
                               "when its height is below this ratio times its triangles' size.");
    t.add(nestedParam(&P::cells, &SegmentDualParams::thinRatio, i));

    i = {};
    i.key = "vertex_min_dihedral", i.flag = "--vertex-min-dihedral";
    i.jsonKey = "vertex_min_dihedral_deg", i.minimum = 0.0, i.maximum = 180.0, i.unit = "°";
    i.valueName = "DEG", i.decimals = 1, i.thesis = "§5.3.3";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Vertex-dual tets, smallest angle:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Where four Voronoi cells meet, the tet of their sites, or of "
                               "their points on the surfaces when the cells are cut, is kept when "
                               "it and its neighbours have no dihedral angle below this; 180 "
                               "leaves the whole volume to TetGen's tets.");
    t.add(nestedParam(&P::vertexCells, &VertexDualParams::minDihedralDegrees, i));

    i = {};
    i.key = "fill_cut_cells", i.flag = "--fill-cut-cells", i.jsonKey = "fill_cut_cells";
    i.type = ParamType::Flag, i.thesis = "§5.3.3";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Leave &cut Voronoi vertices to TetGen");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Where the four Voronoi cells of a vertex meet a surface, TetGen's "
                               "tets fill the place instead of the tet linking their points on "
                               "the surfaces and their sites (Fig. 5.4).");
    {
        Param<HybridParams> p;
        p.info = i;
        p.get = [](const P &params) { return params.vertexCells.fillCutCells ? 1.0 : 0.0; };
        p.set = [](P &params, double v) { params.vertexCells.fillCutCells = v != 0.0; };
        t.add(std::move(p));
    }

    i = {};
    i.key = "iterations", i.flag = "--iterations", i.jsonKey = "iterations";
    i.type = ParamType::Int, i.minimum = 0, i.maximum = 100000, i.valueName = "N";
    i.thesis = "§5.2";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Volume CVT &iterations:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Lloyd iterations of the volumetric centroidal Voronoi diagram.");
    t.add(memberParam(&P::cvtIterations, i));

    i = {};
    i.key = "surface_iterations", i.flag = "--surface-iterations";
    i.jsonKey = "surface_iterations", i.type = ParamType::Int, i.minimum = 0;
    i.maximum = 100000, i.valueName = "N", i.thesis = "§5.2";
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "Off");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Sur&face site iterations:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Lloyd steps moving the sites whose cell meets a surface to the "
                               "centroid of their restricted cell; 0 turns them off.");
    t.add(memberParam(&P::surfaceIterations, i));

    i = seedParamInfo(
        1073741824, QT_TRANSLATE_NOOP(
                        "stratamesh::Params",
                        "Seed of the initial random sampling: the same seed gives the same mesh."));
    t.add(memberParam(&P::seed, i));

    i = {};
    i.key = "max_warp", i.flag = "--max-warp", i.jsonKey = "max_warp_deg", i.minimum = 0.0;
    i.maximum = 90.0, i.unit = "°", i.valueName = "DEG", i.decimals = 1, i.thesis = "§5.4";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Largest quad &warp:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Angle between the two halves of a prism's or pyramid's quad face "
                               "above which the cell is left to the tets.");
    t.add(nestedParam(&P::cells, &SegmentDualParams::maxQuadWarpDegrees, i));

    i = {};
    i.key = "pyramid_height", i.flag = "--pyramid-height", i.jsonKey = "pyramid_height";
    i.minimum = 1e-3, i.maximum = 2.0, i.valueName = "H", i.decimals = 3, i.thesis = "§5.4";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Transition &pyramid height:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Apex height of a pyramid on a quad face that meets the tets, over "
                               "the square root of the quad's area.");
    t.add(memberParam(&P::pyramidHeightRatio, i));

    i = tetgenParamTable().info("quality");
    t.add(nestedParam(&P::tetgen, &TetgenParams::quality, i));
    return t;
}

} // namespace

const ParamTable<HybridParams> &hybridParamTable()
{
    static const ParamTable<HybridParams> table = makeTable();
    return table;
}

} // namespace stratamesh
