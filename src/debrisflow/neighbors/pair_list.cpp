#include "debrisflow/neighbors/pair_list.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <algorithm>
#include <atomic>
#include <fmt/format.h>
#include <numeric>

namespace debrisflow::neighbors {

void PairList::build(const GridView& grid, const particles::ParticleView& pv) {
    const Index n = pv.n;
    count_.assign(std::size_t(n), 0);
    row_of_.resize(std::size_t(n));
    owner_.clear();
    for (Index i = 0; i < n; ++i) {
        row_of_[std::size_t(i)] = pv.is_fluid(i) ? Index(owner_.size()) : -1;
        if (pv.is_fluid(i)) owner_.push_back(i);
    }
    start_.resize(owner_.size());
    const Index rows = Index(owner_.size());
    const Index blocks = (rows + block_rows - 1) / block_rows;
    // Regions from the previous build's pairs per block; at the first build (or with another
    // number of blocks) from none: that search only counts, and a second one fills.
    if (block_pairs_.size() != std::size_t(blocks)) block_pairs_.assign(std::size_t(blocks), 0);
    for (;;) {
        size_regions();
        Index* jj = j_.data();
        Index* cnt = count_.data();
        std::size_t* start = start_.data();
        std::size_t* found = block_pairs_.data();
        const Index* owner = owner_.data();
        const std::size_t* region = region_.data();
        std::atomic<bool> overflow{false};
        // Each block writes its rows one after another from the start of its region and keeps
        // counting past the region's end (without writing) to learn what it needs.
        exec::for_each(
            blocks,
            [&](Index b) {
                std::size_t at = region[b];
                const std::size_t end = region[b + 1];
                for (Index r = b * block_rows; r < std::min(rows, (b + 1) * block_rows); ++r) {
                    const Index i = owner[r];
                    Index c = 0;
                    start[r] = at;
                    grid.for_each_neighbor(i, pv.pos(i), pv.x, pv.y, pv.z,
                                           [&](Index j, Vec3, Real) {
                                               if (j < i && pv.is_fluid(j)) return;
                                               if (at + std::size_t(c) < end) jj[at + c] = j;
                                               ++c;
                                           });
                    cnt[i] = c;
                    at += std::size_t(c);
                }
                found[b] = at - region[b];
                if (at > end) overflow.store(true, std::memory_order_relaxed);
            },
            exec::dynamic(1));
        if (!overflow.load()) break;
    }
    index_touched(n);
}

// Region b holds block b's pairs at the last count plus a quarter and 8 per row. The storage
// is reallocated (freed first: its content is rewritten) when it must grow or would hold more
// than twice what the regions need.
void PairList::size_regions() {
    const Index rows = Index(owner_.size());
    const std::size_t blocks = block_pairs_.size();
    region_.resize(blocks + 1);
    region_[0] = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
        const Index lo = Index(b) * block_rows, hi = std::min(rows, lo + block_rows);
        region_[b + 1] =
            region_[b] + block_pairs_[b] + block_pairs_[b] / 4 + 8 * std::size_t(hi - lo);
    }
    const std::size_t total = region_[blocks];
    if (total > j_.capacity() || total < j_.capacity() / 2) {
        const double more = double(total) * sizeof(Index) - double(bytes_of(j_));
        if (more > 0) require_memory(more, fmt::format("the SPH pair list ({} entries)", total));
        j_ = std::vector<Index>();
    }
    j_.resize(total);
}

void PairList::compact(const std::vector<std::uint8_t>& keep) {
    const Index n = Index(count_.size());
    std::vector<Index> to(std::size_t(n), -1);
    Index m = 0;
    for (Index i = 0; i < n; ++i)
        if (keep[std::size_t(i)]) to[std::size_t(i)] = m++;
    // Rows stay where they are in the storage: each kept row drops its removed partners in
    // place (the write index never passes the read index) and renumbers the rest, in order, so
    // a fluid-fluid pair stays in the row of its lower index. A kept particle with a row keeps
    // one, at its rank among them.
    std::vector<Index> count(std::size_t(m), 0), row_of(std::size_t(m), -1), owner;
    std::vector<std::size_t> start;
    for (Index i = 0; i < n; ++i) {
        const Index r = to[std::size_t(i)], old = row_of_[std::size_t(i)];
        if (r < 0 || old < 0) continue;
        row_of[std::size_t(r)] = Index(owner.size());
        owner.push_back(r);
        start.push_back(start_[std::size_t(old)]);
        Index* row = j_.data() + start_[std::size_t(old)];
        Index c = 0;
        for (Index k = 0; k < count_[std::size_t(i)]; ++k) {
            const Index j = to[std::size_t(row[k])];
            if (j >= 0) row[c++] = j;
        }
        count[std::size_t(r)] = c;
    }
    count_.swap(count);
    row_of_.swap(row_of);
    owner_.swap(owner);
    start_.swap(start);
    count_block_pairs();
    index_touched(m);
}

// Pairs per block of the present rows: the next build sizes its regions from them.
void PairList::count_block_pairs() {
    const Index rows = Index(owner_.size());
    block_pairs_.assign(std::size_t((rows + block_rows - 1) / block_rows), 0);
    for (Index r = 0; r < rows; ++r)
        block_pairs_[std::size_t(r / block_rows)] += std::size_t(count_[owner_[r]]);
}

void PairList::index_touched(Index n) {
    mask_.assign(std::size_t(n), 0);
    std::uint8_t* mask = mask_.data();
    const Index* jj = j_.data();
    const Index* cnt = count_.data();
    const Index* owner = owner_.data();
    const std::size_t* start = start_.data();
    // Several rows can mark the same j: relaxed atomic stores of the same value.
    exec::for_each(
        Index(owner_.size()),
        [=](Index r) {
            const Index i = owner[r];
            if (cnt[i] == 0) return;
            std::atomic_ref<std::uint8_t>(mask[i]).store(1, std::memory_order_relaxed);
            const Index* row = jj + start[r];
            for (Index k = 0; k < cnt[i]; ++k)
                std::atomic_ref<std::uint8_t>(mask[row[k]]).store(1, std::memory_order_relaxed);
        },
        exec::dynamic(512));
    rows_.clear();
    touched_.clear();
    for (Index i = 0; i < n; ++i) {
        if (cnt[i] > 0) rows_.push_back(i);
        if (mask[i]) touched_.push_back(i);
    }
}

std::size_t PairList::pairs() const {
    return std::accumulate(count_.begin(), count_.end(), std::size_t(0));
}

} // namespace debrisflow::neighbors
