#include "debrisflow/dem/fluid_load.hpp"

namespace debrisflow::dem {

namespace {
template <class T> void gather(std::vector<T>& v, const std::vector<Index>& from) {
    std::vector<T> out(from.size(), T{});
    for (std::size_t i = 0; i < from.size(); ++i)
        if (from[i] >= 0 && std::size_t(from[i]) < v.size()) out[i] = v[std::size_t(from[i])];
    v.swap(out);
}
} // namespace

void FluidLoad::resize(std::size_t n) {
    force.resize(n), u.resize(n), beta.resize(n, 0), impulse.resize(n), felt.resize(n),
        handover.resize(n);
}

void FluidLoad::permute(const std::vector<Index>& perm) {
    gather(force, perm), gather(u, perm), gather(beta, perm), gather(impulse, perm),
        gather(felt, perm);
    gather(handover, perm);
}

void FluidLoad::select(const std::vector<Index>& kept) {
    permute(kept);
}

} // namespace debrisflow::dem
