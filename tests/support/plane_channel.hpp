#pragma once
// The plane channel of the Poiseuille and Couette tests: fluid between plates at z = 0 and
// z = L, periodic in x (12 dp long), driven by a body force F along x or by the top plate
// sliding at top_velocity along x, started from rest without hydrostatic density; and its
// velocity profile per lattice layer.
#include "debrisflow/app/simulation.hpp"
#include <cmath>
#include <fmt/format.h>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace debrisflow::test {

// The case text; `sph` is the body of its [sph] table (sound speed, viscosity model ...).
inline std::string plane_channel_case(double dp, double L, double F, double t_end,
                                      const std::string& sph, double top_velocity = 0) {
    return fmt::format(R"(
dimensions = 2
dp = {0}
[time]
end = {1}
[output]
vtk = false
[physics]
gravity = [{2}, 0]
[domain]
min = [0, {3}]
max = [{4}, {5}]
periodic = ["x"]
[sph]
{6}
[[fluid]]
name = "fluid"
shape = "box"
min = [0, 0]
max = [{4}, {7}]
hydrostatic = false
[[wall]]
name = "bottom"
shape = "plane"
point = [0, 0]
normal = [0, 1]
[[wall]]
name = "top"
shape = "plane"
point = [0, {7}]
normal = [0, -1]
velocity = [{8}, 0]
)",
                       dp, t_end, F, -5 * dp, 12 * dp, L + 5 * dp, sph, L, top_velocity);
}

// Mean x velocity per lattice layer, {z of the layer's centre, u} from the bottom plate up
// (the flow is parallel: layers keep their z).
inline std::vector<std::pair<double, double>> layer_profile(app::Simulation& sim, double dp) {
    std::map<int, std::pair<double, int>> acc;
    const auto& s = sim.particles();
    for (Index i = 0; i < s.size(); ++i) {
        if (s.kind[i] != 0) continue;
        auto& e = acc[int(std::floor(s.z[i] / dp))];
        e.first += s.vx[i];
        e.second += 1;
    }
    std::vector<std::pair<double, double>> out;
    for (auto& [k, e] : acc) out.push_back({(k + 0.5) * dp, e.first / e.second});
    return out;
}

// Runs sim to each of `times` in turn and returns there the L2 error of the fluid's x velocity
// against exact(z, t), relative to the exact profile's norm (printed with `label`).
template <class Exact>
std::vector<double> profile_errors(app::Simulation& sim, const std::vector<double>& times,
                                   Exact&& exact, const std::string& label) {
    std::vector<double> errors;
    for (double t : times) {
        sim.run({"", true, 0, t});
        const auto& s = sim.particles();
        double num = 0, den = 0;
        for (Index i = 0; i < s.size(); ++i) {
            if (s.kind[i] != 0) continue;
            const double ua = exact(s.z[i], t);
            num += (s.vx[i] - ua) * (s.vx[i] - ua);
            den += ua * ua;
        }
        errors.push_back(std::sqrt(num / den));
        std::cout << fmt::format("{} t = {} s: L2 error {:.3e}\n", label, t, errors.back());
    }
    return errors;
}

} // namespace debrisflow::test
