// A part of a caller's progress bar: fractions [0, 1] reported here land in [from, to] of the
// parent, and the parent's cancel stops the part at its next tick (the parent's tick throws).
#pragma once

#include "common/progress.h"

namespace stratamesh {

inline Progress progressRange(Progress &parent, double from, double to)
{
    return Progress([&parent, from, to](double fraction, const std::string &stage) {
        parent.tick(from + (to - from) * fraction, stage);
    });
}

} // namespace stratamesh
