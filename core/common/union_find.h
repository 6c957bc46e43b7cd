// Disjoint sets over 0..n-1 with path halving. A join keeps the lower root, so that the root of a
// set is its lowest element whatever the order of the joins: callers rely on it for labels that
// do not depend on the traversal.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace stratamesh {

class UnionFind {
public:
    explicit UnionFind(int n) : m_parent(static_cast<std::size_t>(n))
    {
        std::iota(m_parent.begin(), m_parent.end(), 0);
    }
    int find(int x)
    {
        while (m_parent[x] != x)
            x = m_parent[x] = m_parent[m_parent[x]];
        return x;
    }
    void join(int a, int b)
    {
        a = find(a);
        b = find(b);
        if (a != b)
            m_parent[std::max(a, b)] = std::min(a, b);
    }
    // Dense labels 0..count-1 in order of first appearance.
    std::vector<int> labels(int &count)
    {
        std::vector<int> label(m_parent.size(), -1), byRoot(m_parent.size(), -1);
        count = 0;
        for (int i = 0; i < static_cast<int>(m_parent.size()); ++i) {
            const int r = find(i);
            if (byRoot[r] < 0)
                byRoot[r] = count++;
            label[i] = byRoot[r];
        }
        return label;
    }

private:
    std::vector<int> m_parent;
};

} // namespace stratamesh
