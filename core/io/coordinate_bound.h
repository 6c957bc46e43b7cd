// The largest coordinate a reader accepts, shared by every reader so that a model read from any
// format can be measured: at |x| <= 1e15 squared distances (1e30) and triple products (1e45) stay
// far below the double overflow (1.8e308), even summed over millions of triangles.
#pragma once

#include "common/message_text.h"
#include "common/translate_noop.h"
#include "io/number_text.h"

#include <cmath>
#include <string>

#ifndef QT_TRANSLATE_NOOP
#endif

namespace stratamesh {

constexpr double maxCoordinate = 1e15;

// An empty pattern when `value` is finite and within maxCoordinate, else what is wrong with it,
// to follow the coordinate as the file writes it ("x coordinate '1e200' is beyond ...").
inline MessageText coordinateProblem(double value)
{
    if (!std::isfinite(value))
        return {QT_TRANSLATE_NOOP("stratamesh::Core", "is not finite (non-finite vertex)")};
    if (std::abs(value) > maxCoordinate)
        return {QT_TRANSLATE_NOOP(
            "stratamesh::Core",
            "is beyond the bound of 1e15 that keeps squared distances and volumes finite")};
    return {};
}

// The first problem among three coordinates ("coordinate 1e+200 is beyond ..."), or an empty
// pattern.
template <class Point>
MessageText pointProblem(const Point &p)
{
    for (int k = 0; k < 3; ++k)
        if (MessageText problem = coordinateProblem(p[k]); !problem.pattern.empty())
            return {QT_TRANSLATE_NOOP("stratamesh::Core", "coordinate %1 %2"),
                    {doubleText(p[k])},
                    {std::move(problem)}};
    return {};
}

} // namespace stratamesh
