#pragma once
#include "debrisflow/neighbors/grid_view_k.hpp"
#include <cstdint>
#include <type_traits>

namespace debrisflow::neighbors {

// The key the cell grid's counting sort orders particle i by: its cell, or with a class array
// 2 cell + class (fluid 0 before the rest), so that each cell lists its fluid first. The first
// pass of CellGrid::build on the host; the same functor on a device.
struct CellKeys {
    GridView grid;
    const Real *x, *y, *z; // coordinates of particle i at x[i * stride] ...
    int stride;
    const std::uint8_t* cls; // null: one class
    Index* key;
    DF_HD void operator()(Index i) const {
        const std::size_t k = std::size_t(i) * std::size_t(stride);
        const Index c = grid.cell_of(x[k], y[k], z[k]);
        key[i] = cls ? 2 * c + (cls[i] != 0) : c;
    }
};
static_assert(std::is_trivially_copyable_v<CellKeys>);

} // namespace debrisflow::neighbors
