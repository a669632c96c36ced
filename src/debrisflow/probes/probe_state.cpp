// What probes keep between samples, for checkpoints (Probe::extra_state).
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/probes/dem_probes.hpp"
#include "debrisflow/probes/flow_instruments.hpp"
#include "debrisflow/probes/flow_probes.hpp"

namespace debrisflow::probes {

// The bodies' distances (keyed body_key + k) and the grains' (keyed by id) in one map.
void SolidCrossing::state(checkpoint::Archive& ar) {
    std::unordered_map<std::uint64_t, Real> all;
    if (!ar.is_loading()) {
        all = last_;
        const std::vector<Real> d = pending_ || !grains_ ? restored_ : grains_->distances(plane_);
        for (std::size_t id = 0; id < d.size(); ++id)
            if (d[id] != unseen_distance) all.emplace(id, d[id]);
    }
    ar(mass_, volume_, all);
    if (!ar.is_loading()) return;
    last_.clear();
    restored_.clear();
    for (const auto& [key, d] : all) {
        if (key >= body_key) {
            last_.emplace(key, d);
            continue;
        }
        if (restored_.size() <= key) restored_.resize(key + 1, unseen_distance);
        restored_[key] = d;
    }
    pending_ = true;
}

void DischargeProbe::extra_state(checkpoint::Archive& ar) {
    solid_.state(ar);
    ar(t_last_, fluid_rate_last_, fluid_cum_, solid_last_, solid_vol_last_, started_);
}

void TrappingProbe::extra_state(checkpoint::Archive& ar) {
    up_.state(ar);
    down_.state(ar);
    ar(up0_, down0_, up_w_, down_w_, opened_);
}

void MassFluxProbe::extra_state(checkpoint::Archive& ar) {
    crossing_.state(ar);
    ar(last_cumulative_, last_t_, started_);
}

void OutletProbe::extra_state(checkpoint::Archive& ar) {
    ar(t_last_, fluid_last_, grain_last_);
}

} // namespace debrisflow::probes
