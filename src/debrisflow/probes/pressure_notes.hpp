#pragma once
#include "debrisflow/io/case_spec.hpp"
#include <string>

namespace debrisflow::probes {

// What a case's wall-pressure probes (`pressure`, `pressure_map`) measure with its wall
// treatment, said at `check` and in the run's log: "" when there is nothing to add. With DBC
// walls (the default) two measured limits apply (docs/validation.md, "The impact peak is
// acoustic" and "Sensors up the wall"): a peak is the model's water hammer, about rho c0 u,
// and the load up a wall after an impact reads low (Lobovsky et al. 2014, sensor 4 at 80 mm:
// -53 % with DBC, -18 % with mDBC).
std::string wall_pressure_note(const io::CaseSpec& spec);

} // namespace debrisflow::probes
