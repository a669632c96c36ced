#pragma once
// The host's stable counting sort by a bounded key: the cell grid's sort and the host space's
// Sorter (exec/host_space.hpp).
#include "debrisflow/core/real.hpp"
#include <vector>

namespace debrisflow::exec {

// order[0 .. n) = the indices 0 .. n-1 sorted stably by keys[i] (in [0, key_count)); start[k]
// = the first sorted position of key k (key_count + 1 entries, start[key_count] = n). `cursor`
// is work space.
inline void counting_sort(const Index* keys, Index n, Index key_count, Index* order,
                          std::vector<Index>& start, std::vector<Index>& cursor) {
    cursor.assign(std::size_t(key_count) + 1, 0);
    for (Index i = 0; i < n; ++i) ++cursor[std::size_t(keys[i]) + 1];
    for (Index k = 0; k < key_count; ++k) cursor[k + 1] += cursor[k];
    start.assign(cursor.begin(), cursor.end());
    for (Index i = 0; i < n; ++i) order[cursor[keys[i]]++] = i;
}

} // namespace debrisflow::exec
