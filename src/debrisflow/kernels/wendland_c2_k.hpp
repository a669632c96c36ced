#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"

namespace debrisflow::kernels {

// Wendland C2 (Wendland 1995; Dehnen & Aly 2012): W = a_D (1 - q/2)^4 (2q + 1), 0 <= q <= 2,
// a_D = 7 / (4 pi h^2) in 2D and 21 / (16 pi h^3) in 3D.
struct WendlandC2 {
    static constexpr const char* name = "wendland_c2";
    // the lattice sum of x dW/dx is 0.997 in 2D (docs/validation.md, hydrostatic tank)
    static constexpr Real default_h_over_dp = Real(1.5);
    Real h = 0, alpha = 0, inv_h = 0;

    WendlandC2() = default;
    WendlandC2(Real h_, int dim) : h(h_), inv_h(1 / h_) {
        constexpr Real pi = 3.14159265358979323846;
        alpha = dim == 2 ? Real(7) / (4 * pi * h * h) : Real(21) / (16 * pi * h * h * h);
    }
    DF_HD Real support() const { return 2 * h; }
    DF_HD DF_HOT_INLINE Real w(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2) return 0;
        const Real t = 1 - Real(0.5) * q;
        return alpha * t * t * t * t * (2 * q + 1);
    }
    // (dW/dr) / r, so that grad W_ij = r_ij * grad_over_r(|r_ij|).
    DF_HD DF_HOT_INLINE Real grad_over_r(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2) return 0;
        const Real t = 1 - Real(0.5) * q;
        return -5 * alpha * t * t * t * inv_h * inv_h;
    }
};

} // namespace debrisflow::kernels
