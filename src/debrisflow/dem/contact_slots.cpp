#include "debrisflow/dem/contact_slots.hpp"
#include <numeric>

namespace debrisflow::dem {

void ContactSlots::permute(const std::vector<Index>& perm) {
    const std::size_t cap = std::size_t(cap_), n = perm.size();
    if (count_.size() != n) return;
    std::vector<Index> count(n), partner(n * cap);
    std::vector<std::uint32_t> key(n * cap);
    std::vector<ContactHistory> hist(n * cap);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t from = std::size_t(perm[i]);
        count[i] = count_[from];
        for (std::size_t k = 0; k < cap; ++k) {
            partner[i * cap + k] = partner_[from * cap + k];
            key[i * cap + k] = key_[from * cap + k];
            hist[i * cap + k] = hist_[from * cap + k];
        }
    }
    count_.swap(count);
    partner_.swap(partner);
    key_.swap(key);
    hist_.swap(hist);
}

std::size_t ContactSlots::slots() const {
    return std::accumulate(count_.begin(), count_.end(), std::size_t(0));
}

} // namespace debrisflow::dem
