#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include <optional>
#include <string>
#include <vector>

namespace debrisflow::dem {

// A named grain or wall material as the case file gives it.
struct Material {
    std::string name;
    std::string law =
        "linear";     // contact law for contacts of this material (see ContactLawRegistry)
    Real density = 0; // [kg/m^3] (grains)
    Real youngs_modulus = 0, poisson = 0.25; // [Pa], [-] (hertz_mindlin, dcdem)
    bool rigid = false;                      // infinitely stiff (E* from the other side only)
    Real kn = 0, kt = 0;                     // linear springs [N/m]
    Real restitution = 0.5, friction = 0.5, rolling_friction = 0;
    Real damping_cn = 1e-5; // dcdem C_n
};

// Per-pair values that override the defaults derived from the two materials.
struct PairOverride {
    std::string a, b;
    std::optional<std::string> law;
    std::optional<Real> kn, kt, restitution, friction, rolling_friction, damping_cn;
};

// Damping ratio of the linear spring-dashpot for restitution e:
// zeta = -ln e / sqrt(pi^2 + ln^2 e) (exact for the linear oscillator).
Real linear_damping_ratio(Real e);

// Tsuji coefficient alpha such that F = k d^1.5 + alpha sqrt(m k) d^0.25 d' (force clamped
// >= 0) rebounds with restitution e. The dimensionless oscillator X'' = -X^1.5 - alpha X^0.25 X'
// shows that e depends on alpha only (Tsuji et al. 1992; Antypov & Elliott 2011); it is
// integrated accurately and inverted by bisection.
Real tsuji_alpha(Real e);
// The least restitution tsuji_alpha accepts (alpha = 22); below it the contact is overdamped
// and the map from e to alpha is ill-conditioned. Case files are checked against it.
inline constexpr Real hertz_min_restitution = 0.01;
// Restitution of that oscillator for a given alpha (the forward map used by tsuji_alpha).
Real tsuji_restitution(Real alpha);

// Hertz compliance (1 - nu^2) / E of one side of a contact (0 for a rigid material):
// 1/E* = the sum over both sides (Johnson 1985, eq. 4.22).
Real hertz_compliance(const Material& m);

// Pair table over all materials: law and parameters of every (i, j) pair. Defaults: the law
// of the grain side (the first of the pair when both are grains: both must agree), linear
// springs as series springs 2 k_i k_j/(k_i + k_j), other coefficients the mean of the two;
// a rigid material contributes nothing to E* and G*.
std::vector<PairParams> build_pair_table(const std::vector<Material>& mats,
                                         const std::vector<PairOverride>& overrides,
                                         const std::string& rolling);

} // namespace debrisflow::dem
