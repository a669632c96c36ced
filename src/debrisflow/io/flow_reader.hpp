#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"

namespace debrisflow::io {

// Cross-section of an inlet normal to its flow [m^2] (2D: its height x 1 m).
Real inlet_area(const InletSpec& in, int dim);
// Reads [[inlet]] blocks (after the [[fluid]] blocks: each inlet adds its buffer as a fluid).
void read_inlets(const ConfigTable& root, CaseSpec& c);
// Reads [[outlet]] blocks.
void read_outlets(const ConfigTable& root, CaseSpec& c);

} // namespace debrisflow::io
