#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"

namespace debrisflow::io {

// Reads [rigid], [[body]] and [[joint]] into c.rigid (after the materials are read).
void read_rigid(const ConfigTable& root, CaseSpec& c);

} // namespace debrisflow::io
