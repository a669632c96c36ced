#pragma once
#include "debrisflow/core/bytes_of.hpp"
#include "debrisflow/neighbors/grid_view_k.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <cstdint>
#include <vector>

namespace debrisflow::neighbors {

// Half pair list (each pair once) built from the cell grid with a search radius larger than
// the kernel support by a skin, so that it stays valid while no particle has moved more than
// skin/2 (Verlet 1967). Fluid-fluid pairs are stored in the row of the lower index, fluid-
// boundary pairs in the fluid particle's row, boundary-boundary pairs are left out: boundary
// rows are empty and only fluid particles are searched around, so a model made mostly of
// boundary particles (a long flume, rock shells) costs what its fluid costs.
// Memory follows the pairs, not the longest row: the fluid rows are taken in blocks of
// `block_rows`, and each block writes its rows one after another into its own region of the
// storage, sized from the block's pairs at the previous build plus a quarter (and 8 per row);
// a block that outgrows its region has every region resized from the counts and the search
// redone (the first build, or a large change of the flow). One search per build otherwise.
class PairList {
public:
    static constexpr Index block_rows = 512;

    // Builds the list; `radius` includes the skin. Throws OutOfMemoryError where the storage
    // would not fit in the memory budget (core/memory_budget.hpp).
    void build(const GridView& grid, const particles::ParticleView& pv);
    // Drops the particles with keep[i] == 0 and their pairs and renumbers the rest in order (as
    // ParticleSet::compact): the same list a build at the same positions would give, without
    // the search. An outlet removing a few particles a step no longer forces a rebuild.
    void compact(const std::vector<std::uint8_t>& keep);
    // Start of particle i's row in neighbors(); 0 for a particle without a row (boundary).
    std::size_t begin(Index i) const {
        const Index r = row_of_[std::size_t(i)];
        return r < 0 ? 0 : start_[std::size_t(r)];
    }
    Index count(Index i) const { return count_[i]; }
    const Index* neighbors() const { return j_.data(); }
    std::size_t pairs() const;
    Index particles() const { return Index(count_.size()); } // particles at the last build
    // Particles with a non-empty row (ascending): the fluid, where pair loops start.
    const std::vector<Index>& rows() const { return rows_; }
    // Particles in any pair, as i or j (ascending), and the same as a 0/1 mask over all
    // particles: the only ones a pair loop can give a non-zero sum (in a long flume most
    // boundary particles are in no pair, and loops skip them).
    const std::vector<Index>& touched() const { return touched_; }
    const std::uint8_t* touched_mask() const { return mask_.data(); }
    // Bytes allocated for the list.
    std::size_t bytes() const {
        return bytes_of(count_, row_of_, j_, rows_, touched_, mask_, start_, owner_, region_,
                        block_pairs_);
    }

private:
    void index_touched(Index n);
    void size_regions();
    void count_block_pairs();

    std::vector<Index> count_, j_;
    std::vector<Index> row_of_;            // particle -> its row (fluid), -1 (boundary: no row)
    std::vector<Index> owner_;             // row -> its particle
    std::vector<std::size_t> start_;       // row -> start of its entries in j_
    std::vector<std::size_t> region_;      // block b's region: [region_[b], region_[b + 1])
    std::vector<std::size_t> block_pairs_; // pairs of each block at the last build or compaction
    std::vector<Index> rows_, touched_;
    std::vector<std::uint8_t> mask_;
};

} // namespace debrisflow::neighbors
