// What probes keep between samples, for checkpoints (Probe::extra_state).
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/probes/dem_probes.hpp"
#include "debrisflow/probes/flow_instruments.hpp"
#include "debrisflow/probes/flow_probes.hpp"

namespace debrisflow::probes {

void SolidCrossing::state(checkpoint::Archive& ar) {
    ar(mass_, volume_, last_);
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
