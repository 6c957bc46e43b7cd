#include "hybrid/cell_faces.h"

#include <algorithm>

namespace stratamesh {

namespace {

CellFace tri(int a, int b, int c)
{
    return {{a, b, c, -1}, 3};
}
CellFace quad(int a, int b, int c, int d)
{
    return {{a, b, c, d}, 4};
}

} // namespace

std::vector<CellFace> outwardFaces(const Cell &c)
{
    const auto &n = c.nodes;
    switch (c.type) {
    case CellType::Tet:
        return {tri(n[0], n[2], n[1]), tri(n[0], n[1], n[3]), tri(n[0], n[3], n[2]),
                tri(n[1], n[2], n[3])};
    case CellType::Pyramid:
        return {quad(n[0], n[3], n[2], n[1]), tri(n[0], n[1], n[4]), tri(n[1], n[2], n[4]),
                tri(n[2], n[3], n[4]), tri(n[3], n[0], n[4])};
    case CellType::Prism:
        return {tri(n[0], n[2], n[1]), tri(n[3], n[4], n[5]), quad(n[0], n[1], n[4], n[3]),
                quad(n[1], n[2], n[5], n[4]), quad(n[2], n[0], n[3], n[5])};
    }
    return {};
}

std::vector<std::array<int, 4>> cornerTets(const Cell &c)
{
    const auto &n = c.nodes;
    switch (c.type) {
    case CellType::Tet:
        return {{n[0], n[1], n[2], n[3]}};
    case CellType::Pyramid:
        return {{n[0], n[1], n[3], n[4]},
                {n[1], n[2], n[0], n[4]},
                {n[2], n[3], n[1], n[4]},
                {n[3], n[0], n[2], n[4]}};
    case CellType::Prism:
        return {{n[0], n[1], n[2], n[3]}, {n[1], n[2], n[0], n[4]}, {n[2], n[0], n[1], n[5]},
                {n[3], n[5], n[4], n[0]}, {n[4], n[3], n[5], n[1]}, {n[5], n[4], n[3], n[2]}};
    }
    return {};
}

std::array<int, 4> faceKey(const CellFace &face)
{
    std::array<int, 4> key = face.nodes;
    // Three or four entries: an insertion sort (std::sort's 16-element branch makes GCC 12 warn
    // -Warray-bounds on a 4-element array).
    const int n = face.size == 4 ? 4 : 3;
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && key[j - 1] > key[j]; --j)
            std::swap(key[j - 1], key[j]);
    return key;
}

} // namespace stratamesh
