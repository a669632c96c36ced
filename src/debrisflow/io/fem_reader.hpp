#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"

namespace debrisflow::io {

// Reads [fem], [[fem_material]], [[solid]], [[node_set]] and [[fem_load]] into c.fem.
void read_fem(const ConfigTable& root, CaseSpec& c, Vec3 gravity);

} // namespace debrisflow::io
