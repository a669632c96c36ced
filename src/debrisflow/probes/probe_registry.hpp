#pragma once
#include "debrisflow/probes/probe.hpp"
#include <memory>
#include <span>
#include <string_view>

namespace debrisflow::probes {

// A probe type that a [[probe]] block names with `type`: its name and the function that reads
// the block's own keys and makes the probe.
struct ProbeType {
    std::string_view name;
    std::unique_ptr<Probe> (*from_config)(const ProbeSetup& setup);
};

// Every probe type, in the order of docs/case_reference.md.
std::span<const ProbeType> probe_types();

// The probe that the [[probe]] block `spec` (one of c.probes) describes. Its type reads its own
// keys; an unknown type or key, or a bad value, is an InputError naming file, line and key.
std::unique_ptr<Probe> make_probe(const io::ProbeSpec& spec, const io::CaseSpec& c);

} // namespace debrisflow::probes
