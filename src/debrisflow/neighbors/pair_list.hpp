#pragma once
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <vector>

namespace debrisflow::neighbors {

// Half pair list (each pair once) built from the cell grid with a search radius larger than
// the kernel support by a skin, so that it stays valid while no particle has moved more than
// skin/2 (Verlet 1967). Fluid-fluid pairs are stored in the row of the lower index, fluid-
// boundary pairs in the fluid particle's row, boundary-boundary pairs are left out: boundary
// rows are empty and only fluid particles are searched around, so a model made mostly of
// boundary particles (a long flume, rock shells) costs what its fluid costs. Fixed capacity
// per particle, grown when a particle overflows it.
class PairList {
public:
    // Builds the list; `radius` includes the skin.
    void build(const GridView& grid, const particles::ParticleView& pv);
    Index begin(Index i) const { return Index(i * capacity_); }
    Index count(Index i) const { return count_[i]; }
    const Index* neighbors() const { return j_.data(); }
    std::size_t pairs() const;
    std::size_t capacity() const { return capacity_; }

private:
    std::size_t capacity_ = 64;
    std::vector<Index> count_, j_;
};

} // namespace debrisflow::neighbors
