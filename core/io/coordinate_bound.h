// The largest coordinate a reader accepts, shared by every reader so that a model read from any
// format can be measured: at |x| <= 1e15 squared distances (1e30) and triple products (1e45) stay
// far below the double overflow (1.8e308), even summed over millions of triangles.
#pragma once

#include "io/number_text.h"

#include <cmath>
#include <string>

namespace stratamesh {

constexpr double maxCoordinate = 1e15;

// Empty when `value` is finite and within maxCoordinate, else what is wrong with it, to follow
// the coordinate as the file writes it ("x coordinate '1e200' is beyond ...").
inline std::string coordinateProblem(double value)
{
    if (!std::isfinite(value))
        return "is not finite (non-finite vertex)";
    if (std::abs(value) > maxCoordinate)
        return "is beyond the bound of 1e15 that keeps squared distances and volumes finite";
    return {};
}

// The first problem among three coordinates ("coordinate 1e+200 is beyond ..."), or empty.
template <class Point>
std::string pointProblem(const Point &p)
{
    for (int k = 0; k < 3; ++k)
        if (std::string problem = coordinateProblem(p[k]); !problem.empty())
            return "coordinate " + doubleText(p[k]) + " " + problem;
    return {};
}

} // namespace stratamesh
