#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"

namespace debrisflow::io {

// Reads [dem], [[material]], [[contact]] and [[grains]] into c.dem (sets c.has_dem when the
// case has grains).
void read_dem(const ConfigTable& root, CaseSpec& c);

// Reads a region shape (box, cylinder, stl), shared with fluids.
ShapeSpec read_shape(const ConfigTable& t, int dim, const std::vector<std::string>& allowed);

} // namespace debrisflow::io
