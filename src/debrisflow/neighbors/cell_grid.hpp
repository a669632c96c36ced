#pragma once
#include "debrisflow/core/bytes_of.hpp"
#include "debrisflow/neighbors/grid_view_k.hpp"
#include <array>
#include <cstdint>
#include <vector>

namespace debrisflow::neighbors {

// Cell list over a box domain, rebuilt by counting sort. Cell edge >= search radius, so the
// 3 x 3 (x 3) stencil finds every neighbour. In 2D (x-z plane) the y direction has one cell.
class CellGrid {
public:
    void configure(Vec3 lo, Vec3 hi, Real radius, int dim, std::array<bool, 3> periodic);
    // Sorts particles into cells; afterwards order() lists particle indices cell by cell.
    // Coordinates of particle i are x[i * stride] ... (stride 3 for arrays of 3-vectors).
    // With a class array (0 or 1 per particle, e.g. fluid and boundary) each cell lists its
    // class-0 particles first and the view can visit them alone (GridView::classes).
    void build(const Real* x, const Real* y, const Real* z, Index n, int stride = 1,
               const std::uint8_t* cls = nullptr);
    GridView view() const;
    const std::vector<Index>& order() const { return order_; }
    // Whether the particles already lie in cell order (order() is the identity).
    bool in_order() const;
    int cell_count() const { return nc_[0] * nc_[1] * nc_[2]; }
    // Bytes allocated for the cells and the sorted order.
    std::size_t bytes() const { return bytes_of(start_, order_, cell_of_, count_); }

private:
    std::array<int, 3> nc_{1, 1, 1};
    GridView view_{};
    std::vector<Index> start_, order_, cell_of_, count_;
};

} // namespace debrisflow::neighbors
