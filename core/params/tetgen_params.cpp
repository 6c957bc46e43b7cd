// The TetGen parameters (thesis §5.2): one entry each; the defaults are TetgenParams'.
#include "common/translate_noop.h"
#include "params/param_tables.h"

namespace stratamesh {

namespace {

ParamTable<TetgenParams> makeTable()
{
    using P = TetgenParams;
    ParamTable<P> t("tetmesh");
    ParamInfo i;

    i = {};
    i.key = "quality", i.flag = "--quality", i.jsonKey = "quality", i.minimum = 0.0;
    i.maximum = 1e6, i.valueName = "R", i.decimals = 3, i.thesis = "§5.2";
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "Off");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Quality (radius-edge ratio):");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Largest circumradius to shortest edge ratio TetGen accepts (its q "
                               "switch); 0 turns quality refinement off.");
    t.add(memberParam(&P::quality, i));

    i = {};
    i.key = "max_volume", i.flag = "--max-volume", i.jsonKey = "max_volume", i.minimum = 0.0;
    i.maximum = 1e300, i.unit = "m³", i.valueName = "V", i.scale = ParamScale::Volume;
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "None");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Maximum tet volume:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Largest volume of a tetrahedron (TetGen's a switch); 0 sets none.");
    t.add(memberParam(&P::maxVolume, i));

    i = {};
    i.key = "time_limit", i.flag = "--time-limit", i.jsonKey = "time_limit_s", i.minimum = 0.0;
    i.maximum = 1e9, i.unit = "s", i.valueName = "S", i.decimals = 0;
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "None");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Time limit per model:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "TetGen is stopped after this time on each model; a raw input "
                               "model can keep it busy for hours. 0 sets none.");
    t.add(memberParam(&P::timeLimitSeconds, i));

    i = {};
    i.key = "memory_limit", i.flag = "--memory-limit", i.jsonKey = "memory_limit_mb";
    i.minimum = 0.0, i.maximum = 1e9, i.unit = "MB", i.valueName = "MB", i.decimals = 0;
    i.offText = QT_TRANSLATE_NOOP("stratamesh::Params", "None");
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Memory &limit per model:");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Address space the TetGen helper may use; 0 sets none.");
    t.add(memberParam(&P::memoryLimitMB, i));

    i = {};
    i.key = "refine_surfaces", i.flag = "--refine-surfaces", i.jsonKey = "refine_surfaces";
    i.type = ParamType::Flag;
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Let TetGen &refine the surfaces");
    i.help = QT_TRANSLATE_NOOP("stratamesh::Params",
                               "Without it every surface triangle is kept as it is (TetGen's Y "
                               "switch), so the meshes show what the surfaces themselves give.");
    t.add(memberParam(&P::refineSurfaces, i));

    i = {};
    i.key = "no_merge", i.flag = "--no-merge", i.jsonKey = "no_merge", i.type = ParamType::Flag;
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "&Keep nearly coplanar triangles apart");
    i.help = QT_TRANSLATE_NOOP(
        "stratamesh::Params",
        "When TetGen refines the surfaces it merges nearly coplanar triangles, which moves region "
        "volumes by about 1e-6; this keeps them exact (its M switch) but refines much more.");
    t.add(memberParam(&P::noMerge, i));
    return t;
}

} // namespace

const ParamTable<TetgenParams> &tetgenParamTable()
{
    static const ParamTable<TetgenParams> table = makeTable();
    return table;
}

} // namespace stratamesh
