#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// Contact law and rolling model indices (positions in ContactLawRegistry / RollingRegistry).
enum class LawId : std::uint8_t { linear = 0, hertz_mindlin = 1, dcdem = 2 };
enum class RollingId : std::uint8_t { none = 0, constant_torque = 1, epsd = 2 };

// Parameters of one material pair, precomputed at setup. Per-contact quantities (effective
// radius and mass, overlap) are supplied by the contact loop.
struct PairParams {
    LawId law = LawId::linear;
    RollingId rolling = RollingId::none;
    Real kn = 0, kt = 0;         // linear springs [N/m]
    Real e_star = 0, g_star = 0; // effective Young's and shear moduli [Pa] (Hertz, DCDEM)
    // linear: damping ratio zeta; hertz_mindlin: Tsuji coefficient alpha(e); dcdem: C_n.
    Real damping = 0;
    Real mu = 0;      // Coulomb friction coefficient
    Real mu_roll = 0; // rolling friction coefficient (lever arm / effective radius)
    Real restitution = 1;
    // linear law's dashpots per sqrt(m*): 2 zeta sqrt(k_n) and 2 zeta sqrt(k_t)
    // (set_linear_damping)
    Real linear_gn = 0, linear_gt = 0;
    DF_HD void set_linear_damping(Real zeta) {
        damping = zeta;
        linear_gn = 2 * zeta * std::sqrt(kn);
        linear_gt = 2 * zeta * std::sqrt(kt);
    }
};
static_assert(std::is_trivially_copyable_v<PairParams>);

// Read-only table of pair parameters indexed [material_i * count + material_j]; wall
// materials are entries of the same table.
struct PairTable {
    const PairParams* params;
    int count;
    DF_HD const PairParams& operator()(int a, int b) const { return params[a * count + b]; }
};

} // namespace debrisflow::dem
