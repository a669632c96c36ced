#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include <algorithm>
#include <cmath>
#include <string>

namespace debrisflow::fem {

// A solid material chosen by name: "linear_elastic", or "mazars" (concrete: isotropic damage
// in tension, Mazars 1986). Either may erode elements whose largest principal strain exceeds
// erosion_strain (> 0; the retaining-dam paper used 0.05).
struct FemMaterial {
    std::string name, model = "linear_elastic";
    Real density = 0, youngs_modulus = 0, poisson = 0;
    Real damage_threshold = 0;           // kappa_0: equivalent strain at the onset of damage
    Real damage_a = 1, damage_b = 10000; // Mazars tension parameters A_t, B_t
    Real erosion_strain = 0;             // 0: no erosion
    bool damages() const { return model == "mazars"; }
};

// Mazars equivalent strain from the principal strains: sqrt(sum <e_i>_+^2).
DF_HD inline Real mazars_equivalent_strain(const Real e[3]) {
    Real s = 0;
    for (int k = 0; k < 3; ++k)
        if (e[k] > 0) s += e[k] * e[k];
    return std::sqrt(s);
}

// Mazars (1986) tension damage for the largest equivalent strain reached, kappa:
// D = 1 - kappa_0 (1 - A) / kappa - A exp(-B (kappa - kappa_0)) for kappa > kappa_0, else 0.
DF_HD inline Real mazars_damage(const FemMaterial& m, Real kappa) {
    if (kappa <= m.damage_threshold) return 0;
    const Real d = 1 - m.damage_threshold * (1 - m.damage_a) / kappa -
                   m.damage_a * std::exp(-m.damage_b * (kappa - m.damage_threshold));
    return std::clamp(d, Real(0), Real(0.9999));
}

} // namespace debrisflow::fem
