#include "debrisflow/probes/pressure_notes.hpp"
#include <fmt/format.h>

namespace debrisflow::probes {

std::string wall_pressure_note(const io::CaseSpec& spec) {
    if (spec.fluids.empty() && spec.inlets.empty()) return "";
    std::string names;
    int count = 0;
    for (const auto& p : spec.probes)
        if (p.type == "pressure" || p.type == "pressure_map") {
            if (count++ < 3) names += (names.empty() ? "'" : ", '") + p.name + "'";
        }
    if (count == 0) return "";
    if (count > 3) names += fmt::format(" and {} more", count - 3);
    const std::string peaks = fmt::format(
        "note: wall pressure probes {}: an instantaneous peak is the model's water hammer, about "
        "rho c0 u, which follows c0 = {:.4g} m/s, dp and the sampling interval, not the flow "
        "(Lobovsky's dam break: 3 to 7 times the measured peak); the 50 ms window's peak "
        "(peak_mean_50ms in summary.json) follows the measured impact load at the foot of a wall "
        "within 25 %",
        names, spec.sph.c0);
    if (spec.sph.boundary != "dbc") return peaks;
    return peaks + "; with DBC walls (sph.boundary = \"dbc\") the load up a wall after an impact "
                   "also reads low (Lobovsky's sensor at 80 mm: -53 %, with mDBC -18 %): for "
                   "loads on a wall set sph.boundary = \"mdbc\" (docs/validation.md)";
}

} // namespace debrisflow::probes
