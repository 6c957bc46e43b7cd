#include "common/translate_noop.h"
#include "param_table.h"

namespace stratamesh {

// The one text of every algorithm's seed: only its range and what it reproduces differ.
ParamInfo seedParamInfo(double maximum, const char *help)
{
    ParamInfo i;
    i.key = "seed", i.flag = "--seed", i.jsonKey = "seed", i.type = ParamType::Seed;
    i.minimum = 0, i.maximum = maximum, i.valueName = "S";
    i.label = QT_TRANSLATE_NOOP("stratamesh::Params", "Ra&ndom seed:");
    i.help = help;
    return i;
}

} // namespace stratamesh
