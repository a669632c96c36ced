#include "debrisflow/dem/contact_slots.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <numeric>

namespace debrisflow::dem {

void ContactSlots::permute(const std::vector<Index>& perm) {
    if (count_.size() != perm.size()) return;
    remap(perm);
}

void ContactSlots::remap(const std::vector<Index>& from) {
    if (count_.empty()) return; // never built: nothing to carry
    const std::size_t cap = std::size_t(cap_), n = from.size();
    std::vector<Index> count(n, 0), partner(n * cap);
    std::vector<std::uint32_t> key(n * cap);
    std::vector<Vec3> xi(n * cap), mroll(rolling_ ? n * cap : 0);
    exec::for_each(Index(n), [&](Index row) {
        const std::size_t i = std::size_t(row);
        if (from[i] < 0) return;
        const std::size_t f = std::size_t(from[i]);
        count[i] = count_[f];
        for (std::size_t k = 0; k < cap; ++k) {
            partner[i * cap + k] = partner_[f * cap + k];
            key[i * cap + k] = key_[f * cap + k];
            xi[i * cap + k] = xi_[f * cap + k];
            if (rolling_) mroll[i * cap + k] = mroll_[f * cap + k];
        }
    });
    count_.swap(count);
    partner_.swap(partner);
    key_.swap(key);
    xi_.swap(xi);
    mroll_.swap(mroll);
}

std::size_t ContactSlots::slots() const {
    return std::accumulate(count_.begin(), count_.end(), std::size_t(0));
}

} // namespace debrisflow::dem
