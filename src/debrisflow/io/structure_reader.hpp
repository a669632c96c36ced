#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"

namespace debrisflow::io {

// Gravity tilted by the slope of a [[structure]] of type "flume" (slope_deg or slope_percent):
// g (sin t, 0, -cos t), so that the flume bed is the plane z = bed and the flow runs along +x.
// Returns `gravity` unchanged when no flume gives a slope.
Vec3 flume_gravity(const ConfigTable& root, Vec3 gravity);

// Expands each [[structure]] (flume, check_dam, slit_dam, baffles, gate, hopper) into one
// named wall made of solid boxes (type "boxes"), for the SPH (boundary particles) and the DEM
// (exact faces) alike. Call after the fluid, grain and body blocks are read.
void read_structures(const ConfigTable& root, CaseSpec& c);

} // namespace debrisflow::io
