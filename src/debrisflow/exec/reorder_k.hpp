#pragma once
// The small per-item steps a resident loop (sph/resident_sph.hpp, dem/resident_dem.hpp) uses
// to keep its cell grid and to reorder its arrays by cell: host/device functors.
#include "debrisflow/core/real.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <cstddef>
#include <type_traits>

namespace debrisflow::exec {

// start[c] = the first sorted position whose key is >= c (a binary search over the keys in
// sorted order), for c in [0, key_count]: with keys sorted stably, cell c's particles are
// order[start[c]] .. order[start[c+1]-1], as CellGrid's counting sort leaves them.
struct CellStarts {
    const Index* key;   // per particle
    const Index* order; // sorted position -> particle
    Index n;
    Index* start;
    DF_HD void operator()(Index c) const {
        Index lo = 0, hi = n;
        while (lo < hi) {
            const Index mid = lo + (hi - lo) / 2;
            if (key[order[mid]] < c)
                lo = mid + 1;
            else
                hi = mid;
        }
        start[c] = lo;
    }
};

// out[i] = in[order[i]] for `width` values per item (a permutation applied by gathering).
template <class T> struct GatherByOrder {
    const T* in;
    const Index* order;
    T* out;
    int width;
    DF_HD void operator()(Index i) const {
        const std::size_t to = std::size_t(i) * width, from = std::size_t(order[i]) * width;
        for (int k = 0; k < width; ++k) out[to + k] = in[from + k];
    }
};

// Whether sorted position i holds another particle than i (the particles are not in order).
struct OutOfOrder {
    const Index* order;
    DF_HD bool operator()(Index i) const { return order[i] != i; }
};

static_assert(std::is_trivially_copyable_v<CellStarts>);
static_assert(std::is_trivially_copyable_v<OutOfOrder>);

} // namespace debrisflow::exec
