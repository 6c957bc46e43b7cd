#include "model/model.h"

namespace stratamesh {

std::size_t Model::triangleCount() const
{
    std::size_t n = 0;
    for (const Surface &s : surfaces)
        n += s.triangles.size();
    return n;
}

} // namespace stratamesh
