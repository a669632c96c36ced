#pragma once
#include "debrisflow/dem/contact_force_k.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <algorithm>
#include <cstdint>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::dem {

// Per-grain contact candidates with their history, in fixed-capacity slots per grain:
// grain i's slots are [i*capacity, i*capacity + count(i)). Each slot holds the partner's index
// (a grain or a wall primitive), a persistent key (the partner grain's id or the primitive
// index) and the contact history. Rebuilding keeps the history of every pair whose key
// reappears, so tangential springs survive neighbour rebuilds; permute() moves the slots with
// their grains, so they also survive reordering.
class ContactSlots {
public:
    // Rebuilds the slots: candidates(i, emit) calls emit(partner, key) for grain i's partners.
    // Grows the capacity when a grain overflows it.
    template <class Candidates> void build(Index n, const Candidates& candidates);
    void permute(const std::vector<Index>& perm);
    // General reindexing: new grain i takes old grain from[i]'s slots; from[i] < 0 is a new
    // grain without contacts. Used when grains are removed (outlets) or inserted (feeds).
    void remap(const std::vector<Index>& from);
    void clear_history() {
        std::fill(xi_.begin(), xi_.end(), Vec3{});
        std::fill(mroll_.begin(), mroll_.end(), Vec3{});
    }
    // Whether the slots keep a rolling moment (the elastic-plastic rolling model); set before
    // the first build.
    void keep_rolling(bool on) { rolling_ = on; }

    Index capacity() const { return cap_; }
    Index count(Index i) const { return count_[std::size_t(i)]; }
    const Index* partners() const { return partner_.data(); }
    const Index* counts() const { return count_.data(); }
    Vec3* tangential() { return xi_.data(); }
    Vec3* rolling() { return rolling_ ? mroll_.data() : nullptr; }
    HistoryRef history(std::size_t slot) {
        return {xi_.data() + slot, rolling_ ? mroll_.data() + slot : nullptr};
    }
    std::size_t slots() const;
    // Saves or restores partners, keys and contact histories (dem/dem_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    Index cap_ = 8;
    std::vector<Index> count_, partner_, old_count_;
    std::vector<std::uint32_t> key_, old_key_;
    bool rolling_ = false;
    std::vector<Vec3> xi_, old_xi_, mroll_, old_mroll_; // mroll_ empty without rolling
};

template <class Candidates> void ContactSlots::build(Index n, const Candidates& candidates) {
    const bool had = count_.size() == std::size_t(n);
    const Index old_cap = cap_;
    old_count_.swap(count_);
    old_key_.swap(key_);
    old_xi_.swap(xi_);
    old_mroll_.swap(mroll_);
    if (!had) old_count_.assign(std::size_t(n), 0);
    for (;;) {
        const Index cap = cap_;
        count_.assign(std::size_t(n), 0);
        partner_.resize(std::size_t(n) * std::size_t(cap));
        key_.resize(partner_.size());
        xi_.assign(partner_.size(), Vec3{});
        mroll_.assign(rolling_ ? partner_.size() : 0, Vec3{});
        const bool had_rolling = old_mroll_.size() == old_xi_.size();
        const Index worst = exec::max_of(
            n, Index(0),
            [&](Index i) {
                const std::size_t base = std::size_t(i) * std::size_t(cap);
                const std::size_t old_base = std::size_t(i) * std::size_t(old_cap);
                const Index old_c = old_count_[std::size_t(i)];
                Index c = 0;
                candidates(i, [&](Index partner, std::uint32_t key) {
                    if (c < cap) {
                        partner_[base + std::size_t(c)] = partner;
                        key_[base + std::size_t(c)] = key;
                        for (Index k = 0; k < old_c; ++k)
                            if (old_key_[old_base + std::size_t(k)] == key) {
                                const std::size_t to = base + std::size_t(c),
                                                  from = old_base + std::size_t(k);
                                xi_[to] = old_xi_[from];
                                if (rolling_ && had_rolling) mroll_[to] = old_mroll_[from];
                                break;
                            }
                    }
                    ++c;
                });
                count_[std::size_t(i)] = c;
                return c;
            },
            exec::dynamic(256, 4097));
        if (worst <= cap) return;
        cap_ = worst + worst / 4 + 2; // history still in old_*: retry with room
    }
}

} // namespace debrisflow::dem
