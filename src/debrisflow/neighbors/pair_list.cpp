#include "debrisflow/neighbors/pair_list.hpp"
#include <algorithm>
#include <numeric>

namespace debrisflow::neighbors {

void PairList::build(const GridView& grid, const particles::ParticleView& pv) {
    const Index n = pv.n;
    count_.assign(std::size_t(n), 0);
    for (;;) {
        j_.resize(std::size_t(n) * capacity_);
        Index worst = 0;
        const Index cap = Index(capacity_);
        Index* jj = j_.data();
        Index* cnt = count_.data();
#pragma omp parallel for schedule(dynamic, 512) reduction(max : worst)
        for (Index i = 0; i < n; ++i) {
            Index c = 0;
            Index* out = jj + std::size_t(i) * cap;
            if (pv.is_fluid(i))
                grid.for_each_neighbor(i, pv.pos(i), pv.x, pv.y, pv.z, [&](Index j, Vec3, Real) {
                    if (j < i && pv.is_fluid(j)) return;
                    if (c < cap) out[c] = j;
                    ++c;
                });
            cnt[i] = c;
            worst = std::max(worst, c);
        }
        if (worst <= cap) return;
        capacity_ = std::size_t(worst) + std::size_t(worst) / 4 + 8;
    }
}

std::size_t PairList::pairs() const {
    return std::accumulate(count_.begin(), count_.end(), std::size_t(0));
}

} // namespace debrisflow::neighbors
