#include "debrisflow/probes/probe_registry.hpp"
#include "debrisflow/probes/body_probe.hpp"
#include "debrisflow/probes/dem_probes.hpp"
#include "debrisflow/probes/fem_probes.hpp"
#include "debrisflow/probes/flow_instruments.hpp"
#include "debrisflow/probes/flow_probes.hpp"
#include "debrisflow/probes/hazard_map.hpp"
#include "debrisflow/probes/pressure_map.hpp"
#include "debrisflow/probes/runout_probe.hpp"
#include "debrisflow/probes/sph_probes.hpp"
#include "debrisflow/probes/wall_force_probe.hpp"
#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace debrisflow::probes {

namespace {
template <class P> constexpr ProbeType type_of() {
    return {P::type_name, &P::from_config};
}

// One line per probe type.
constexpr std::array types = {
    type_of<PressureProbe>(),    type_of<GaugeProbe>(),         type_of<VelocityProbe>(),
    type_of<FrontProbe>(),       type_of<WallForceProbe>(),     type_of<PressureMapProbe>(),
    type_of<FlowSectionProbe>(), type_of<FluidRunupProbe>(),    type_of<HazardMapProbe>(),
    type_of<SectionProbe>(),     type_of<KineticEnergyProbe>(), type_of<RunupProbe>(),
    type_of<MassFluxProbe>(),    type_of<DischargeProbe>(),     type_of<TrappingProbe>(),
    type_of<DepositProbe>(),     type_of<BodyProbe>(),          type_of<FemDisplacementProbe>(),
    type_of<FemForceProbe>(),    type_of<FemFaceLoadProbe>(),   type_of<DomainExitProbe>(),
    type_of<RunoutProbe>(),
};
} // namespace

std::span<const ProbeType> probe_types() {
    return types;
}

std::unique_ptr<Probe> make_probe(const io::ProbeSpec& spec, const io::CaseSpec& c) {
    const io::ConfigTable& t = *spec.table;
    std::vector<std::string> names;
    for (const auto& type : types) names.emplace_back(type.name);
    const std::string name = t.choice("type", names);
    std::size_t index = 0;
    while (index < c.probes.size() && c.probes[index].name != spec.name) ++index;
    // choice() has rejected any name not in the list
    const auto& type = *std::find_if(types.begin(), types.end(),
                                     [&](const ProbeType& k) { return k.name == name; });
    auto probe = type.from_config({t, c, spec, std::span(c.probes).first(index)});
    t.finish();
    return probe;
}

} // namespace debrisflow::probes
