#include "debrisflow/neighbors/pair_list.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <algorithm>
#include <atomic>
#include <numeric>

namespace debrisflow::neighbors {

void PairList::build(const GridView& grid, const particles::ParticleView& pv) {
    const Index n = pv.n;
    count_.assign(std::size_t(n), 0);
    row_of_.resize(std::size_t(n));
    Index rows = 0;
    for (Index i = 0; i < n; ++i) row_of_[std::size_t(i)] = pv.is_fluid(i) ? rows++ : -1;
    for (;;) {
        j_.resize(std::size_t(rows) * capacity_);
        const Index cap = Index(capacity_);
        Index* jj = j_.data();
        Index* cnt = count_.data();
        const Index* row_of = row_of_.data();
        const auto row = [&](Index i) {
            Index c = 0;
            Index* out = jj + std::size_t(row_of[i] < 0 ? 0 : row_of[i]) * cap;
            if (pv.is_fluid(i))
                grid.for_each_neighbor(i, pv.pos(i), pv.x, pv.y, pv.z, [&](Index j, Vec3, Real) {
                    if (j < i && pv.is_fluid(j)) return;
                    if (c < cap) out[c] = j;
                    ++c;
                });
            cnt[i] = c;
            return c;
        };
        const Index worst = exec::max_of(n, Index(0), row, exec::dynamic(512));
        if (worst <= cap) break;
        capacity_ = std::size_t(worst) + std::size_t(worst) / 4 + 8;
    }
    index_touched(n);
}

void PairList::compact(const std::vector<std::uint8_t>& keep) {
    const Index n = Index(count_.size());
    std::vector<Index> to(std::size_t(n), -1);
    Index m = 0;
    for (Index i = 0; i < n; ++i)
        if (keep[std::size_t(i)]) to[std::size_t(i)] = m++;
    // In place, rows in ascending order: row i moves to row to[i] <= i, whose old content has
    // already been moved, and within a row the write index never passes the read index. Only
    // the non-empty rows are touched (a flume's boundary rows are empty). Order is kept, so a
    // fluid-fluid pair stays in the row of its lower index.
    // A kept particle with a row keeps one, at its rank among them (<= its old row).
    std::vector<Index> count(std::size_t(m), 0), row_of(std::size_t(m), -1);
    Index rows = 0;
    for (Index i = 0; i < n; ++i)
        if (to[std::size_t(i)] >= 0 && row_of_[std::size_t(i)] >= 0)
            row_of[std::size_t(to[std::size_t(i)])] = rows++;
    const std::size_t cap = capacity_;
    for (const Index i : rows_) {
        const Index r = to[std::size_t(i)];
        if (r < 0) continue;
        const Index* row = j_.data() + begin(i);
        Index* out = j_.data() + std::size_t(row_of[std::size_t(r)]) * cap;
        Index c = 0;
        for (Index k = 0; k < count_[std::size_t(i)]; ++k) {
            const Index j = to[std::size_t(row[k])];
            if (j >= 0) out[c++] = j;
        }
        count[std::size_t(r)] = c;
    }
    count_.swap(count);
    row_of_.swap(row_of);
    j_.resize(std::size_t(rows) * cap);
    index_touched(m);
}

void PairList::index_touched(Index n) {
    mask_.assign(std::size_t(n), 0);
    std::uint8_t* mask = mask_.data();
    const Index* jj = j_.data();
    const Index* cnt = count_.data();
    const Index* row_of = row_of_.data();
    const std::size_t cap = capacity_;
    // Several rows can mark the same j: relaxed atomic stores of the same value.
    exec::for_each(
        n,
        [=](Index i) {
            if (cnt[i] == 0) return;
            std::atomic_ref<std::uint8_t>(mask[i]).store(1, std::memory_order_relaxed);
            const Index* row = jj + std::size_t(row_of[i]) * cap;
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
