#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace debrisflow::dem {

// Parameters of one material pair, precomputed at setup. Per-contact quantities (effective
// radius and mass, overlap) are supplied by the contact loop.
struct PairParams {
    std::uint8_t law = 0;        // the pair's contact law: its position in ContactLawRegistry
    std::uint8_t rolling = 0;    // its rolling-resistance model: position in RollingRegistry
    Real kn = 0, kt = 0;         // linear springs [N/m]
    Real e_star = 0, g_star = 0; // effective Young's and shear moduli [Pa] (elastic laws)
    // linear: damping ratio zeta; Hertz-type laws: Tsuji coefficient alpha(e); dcdem: C_n.
    Real damping = 0;
    Real mu = 0;      // Coulomb friction coefficient
    Real mu_roll = 0; // rolling friction coefficient (lever arm / effective radius)
    Real restitution = 1;
    // linear law's dashpots per sqrt(m*): 2 zeta sqrt(k_n) and 2 zeta sqrt(k_t)
    // (set_linear_damping)
    Real linear_gn = 0, linear_gt = 0;
    // Constants a law keeps beyond the shared ones; their meaning is stated in the law's file
    // (dem/laws/), which alone sets and reads them.
    Real law_constant[2] = {0, 0};
    DF_HD void set_linear_damping(Real zeta) {
        damping = zeta;
        linear_gn = 2 * zeta * std::sqrt(kn);
        linear_gt = 2 * zeta * std::sqrt(kt);
    }
};
static_assert(std::is_trivially_copyable_v<PairParams>);

// Read-only table of pair parameters indexed [material_i * count + material_j]; wall
// materials are entries of the same table. `adhesive`: some pair's law acts beyond touch
// (ContactLaws::reach), so the contact loops test the reach of pairs that do not overlap.
struct PairTable {
    const PairParams* params;
    int count;
    bool adhesive = false;
    DF_HD const PairParams& operator()(int a, int b) const { return params[a * count + b]; }
};

} // namespace debrisflow::dem
