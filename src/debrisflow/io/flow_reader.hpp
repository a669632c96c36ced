#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"

namespace debrisflow::io {

// Reads [[inlet]] blocks (after the [[fluid]] blocks: each inlet adds its buffer as a fluid).
void read_inlets(const ConfigTable& root, CaseSpec& c);
// Reads [[outlet]] blocks.
void read_outlets(const ConfigTable& root, CaseSpec& c);

} // namespace debrisflow::io
