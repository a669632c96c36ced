#pragma once
// Stream compaction in a resident loop (sph/resident_sph.hpp, dem/resident_dem.hpp): items are
// flagged keep = 1 or 0, the flags' exclusive scan gives each kept item its new place, and
// every array is moved there. Host/device functors.
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include <cstddef>
#include <type_traits>

namespace debrisflow::exec {

// out[at[i]] = in[i] for the items with keep[i] (`at` the exclusive scan of keep), `width`
// values per item.
template <class T> struct ScatterKept {
    const T* in;
    const Index* keep;
    const Index* at;
    T* out;
    int width;
    DF_HD void operator()(Index i) const {
        if (!keep[i]) return;
        const std::size_t to = std::size_t(at[i]) * width, from = std::size_t(i) * width;
        for (int k = 0; k < width; ++k) out[to + k] = in[from + k];
    }
};

// order[at[i]] = i for the items with keep[i]: the kept items in their order, as an order that
// GatherByOrder (exec/reorder_k.hpp) applies to any array.
struct KeptOrder {
    const Index* keep;
    const Index* at;
    Index* order;
    DF_HD void operator()(Index i) const {
        if (keep[i]) order[at[i]] = i;
    }
};

// Whether item i is dropped (keep[i] = 0).
struct Dropped {
    const Index* keep;
    DF_HD bool operator()(Index i) const { return keep[i] == 0; }
};

// out[i] = 1 - keep[i].
struct Complement {
    const Index* keep;
    Index* out;
    DF_HD void operator()(Index i) const { out[i] = 1 - keep[i]; }
};

static_assert(std::is_trivially_copyable_v<KeptOrder>);
static_assert(std::is_trivially_copyable_v<Dropped>);
static_assert(std::is_trivially_copyable_v<Complement>);

} // namespace debrisflow::exec
