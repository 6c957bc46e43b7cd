// Dense indices for the group ids a file gives its cells (surface, region or line ids), through a
// map rather than an array sized by the largest id: one cell claiming id 2147483647 costs one
// group, not two billion names.
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace stratamesh {

class GroupIndex {
public:
    // Ids must be >= 0 (the caller refuses others with the file's position).
    void add(long long id) { m_sparse.emplace(id, -1); }

    // Ids below `dense` keep their value as index, so the file's names and its other references
    // (region sides) stay aligned: `dense` covers the `named` ids, and all ids when they fit in
    // named + the number of distinct ids. Other ids follow in increasing order.
    void number(std::size_t named)
    {
        const long long largest = m_sparse.empty() ? -1 : m_sparse.rbegin()->first;
        const long long fit = static_cast<long long>(named + m_sparse.size());
        m_dense = largest < fit ? std::max(largest + 1, static_cast<long long>(named))
                                : static_cast<long long>(named);
        int next = static_cast<int>(m_dense);
        for (auto it = m_sparse.begin(); it != m_sparse.end();)
            if (it->first < m_dense)
                it = m_sparse.erase(it);
            else
                (it++)->second = next++;
        m_count = next;
    }

    // -1 for an id that was never added.
    int indexOf(long long id) const
    {
        if (id >= 0 && id < m_dense)
            return static_cast<int>(id);
        const auto it = m_sparse.find(id);
        return it == m_sparse.end() ? -1 : it->second;
    }

    int count() const { return m_count; }

    // A name per index: the file's own names first, then "<kind>_<id+1>".
    std::vector<std::string> names(std::vector<std::string> named, const char *kind) const
    {
        named.resize(static_cast<std::size_t>(m_count));
        auto fill = [&](long long id, int index) {
            std::string &name = named[static_cast<std::size_t>(index)];
            if (name.empty())
                name = std::string(kind) + "_" + std::to_string(id + 1);
        };
        for (long long id = 0; id < m_dense; ++id)
            fill(id, static_cast<int>(id));
        for (const auto &[id, index] : m_sparse)
            fill(id, index);
        return named;
    }

private:
    std::map<long long, int> m_sparse;
    long long m_dense = 0;
    int m_count = 0;
};

} // namespace stratamesh
