#pragma once
#include "debrisflow/dem/wall_bins_k.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include <cstddef>
#include <vector>

namespace debrisflow::dem {

// Builds the bins of the active wall primitives (dem/wall_bins_k.hpp) on the host, at each
// neighbour rebuild: a counting pass and a filling pass over the primitives' widened boxes.
class WallBins {
public:
    // Fewer active primitives than this are searched one by one (planes and boxes of a flume).
    static constexpr Index min_primitives = 64;
    // A face whose widened box covers more cells than this stays out of the bins.
    static constexpr long max_cells_per_face = 64;

    // bounds: the active primitives' boxes (unbounded: planes); reach: the largest grain
    // radius plus the search margin; dim 2: one cell across y.
    void build(const std::vector<PrimitiveBounds>& bounds, Real reach, int dim);
    // The bins with pointers into this object's arrays.
    WallBinsView view() const;
    const std::vector<Index>& start() const { return start_; }
    const std::vector<Index>& items() const { return items_; }
    const std::vector<Index>& always() const { return always_; }
    std::size_t bytes() const {
        return (start_.capacity() + items_.capacity() + always_.capacity()) * sizeof(Index);
    }

private:
    WallBinsView view_{};
    std::vector<Index> start_, items_, always_;
};

} // namespace debrisflow::dem
