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

// The capacity of every row after a build whose longest row held `longest`: a quarter more
// and two, so that rows growing between rebuilds rarely send a build round a second time.
DF_HD constexpr Index slot_capacity_for(Index longest) {
    return longest + longest / 4 + 2;
}

// Per-grain contact candidates with their history, in fixed-capacity slots per grain:
// grain i's slots are [i*capacity, i*capacity + count(i)). The capacity follows the longest
// row of the last build (slot_capacity_for), down as well as up: a stride wider than the rows
// are long only adds memory traffic to every step's contact loop. Each slot holds the partner's
// index (a grain or a wall primitive), a persistent key (the partner grain's id or the primitive
// index) and the contact history. Rebuilding keeps the history of every pair whose key
// reappears, so tangential springs survive neighbour rebuilds; permute() moves the slots with
// their grains, so they also survive reordering.
class ContactSlots {
public:
    // Rebuilds the slots: candidates(i, emit) calls emit(partner, key) for grain i's partners.
    // Takes the capacity the last build's longest row asked for, and builds again with room
    // when a grain overflows it.
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
    // The resident loop (dem/resident_dem.hpp) copies the rows to and from its memory.
    template <class> friend class ResidentDem;
    Index cap_ = 0;      // the rows' stride now
    Index next_cap_ = 2; // the next build's: slot_capacity_for(the last build's longest row)
    std::vector<Index> count_, partner_, old_count_;
    std::vector<std::uint32_t> key_, old_key_;
    bool rolling_ = false;
    std::vector<Vec3> xi_, old_xi_, mroll_, old_mroll_; // mroll_ empty without rolling
};

// One grain's row of a rebuild, written once for the host and a device: the partners that
// candidates(i, emit) names (emit(partner, key)), each with the history of the same key in the
// grain's old row. Returns the number of candidates: a row past the capacity keeps the first
// ones, and the build retries with room.
template <class Candidates> struct SlotRowFill {
    Candidates candidates;
    const Index* old_count;
    const std::uint32_t* old_key;
    const Vec3 *old_xi, *old_mroll; // old_mroll null: the old rows kept no rolling moment
    Index* count;
    Index* partner;
    std::uint32_t* key;
    Vec3 *xi, *mroll; // mroll null: no rolling moment kept
    Index cap, old_cap;
    DF_HD Index operator()(Index i) const {
        const std::size_t base = std::size_t(i) * std::size_t(cap);
        const std::size_t old_base = std::size_t(i) * std::size_t(old_cap);
        const Index old_c = old_count[i];
        Index c = 0;
        candidates(i, [&](Index p, std::uint32_t k) {
            if (c < cap) {
                const std::size_t to = base + std::size_t(c);
                partner[to] = p;
                key[to] = k;
                xi[to] = Vec3{};
                if (mroll) mroll[to] = Vec3{};
                for (Index o = 0; o < old_c; ++o)
                    if (old_key[old_base + std::size_t(o)] == k) {
                        const std::size_t from = old_base + std::size_t(o);
                        xi[to] = old_xi[from];
                        if (mroll && old_mroll) mroll[to] = old_mroll[from];
                        break;
                    }
            }
            ++c;
        });
        count[i] = c;
        return c;
    }
};

template <class Candidates> void ContactSlots::build(Index n, const Candidates& candidates) {
    const bool had = count_.size() == std::size_t(n);
    const Index old_cap = cap_;
    old_count_.swap(count_);
    old_key_.swap(key_);
    old_xi_.swap(xi_);
    old_mroll_.swap(mroll_);
    if (!had) old_count_.assign(std::size_t(n), 0);
    const bool had_rolling = old_mroll_.size() == old_xi_.size();
    Index cap = next_cap_;
    for (;;) {
        count_.assign(std::size_t(n), 0);
        partner_.resize(std::size_t(n) * std::size_t(cap));
        key_.resize(partner_.size());
        xi_.assign(partner_.size(), Vec3{});
        mroll_.assign(rolling_ ? partner_.size() : 0, Vec3{});
        const SlotRowFill<Candidates> fill{candidates,
                                           old_count_.data(),
                                           old_key_.data(),
                                           old_xi_.data(),
                                           had_rolling ? old_mroll_.data() : nullptr,
                                           count_.data(),
                                           partner_.data(),
                                           key_.data(),
                                           xi_.data(),
                                           rolling_ ? mroll_.data() : nullptr,
                                           cap,
                                           old_cap};
        const Index worst = exec::max_of(n, Index(0), fill, exec::dynamic(256, 4097));
        if (worst <= cap) {
            cap_ = cap;
            next_cap_ = slot_capacity_for(worst);
            return;
        }
        cap = slot_capacity_for(worst); // history still in old_*: retry with room
    }
}

} // namespace debrisflow::dem
