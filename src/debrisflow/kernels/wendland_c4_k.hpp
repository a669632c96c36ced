#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"

namespace debrisflow::kernels {

// Wendland C4 (Wendland 1995; Dehnen & Aly 2012, table 1, support 2h):
// W = a_D (1 - q/2)^6 (35/12 q^2 + 3q + 1), 0 <= q <= 2, a_D = 9 / (4 pi h^2) in 2D and
// 495 / (256 pi h^3) in 3D. Smoother than C2 (two more continuous derivatives), so it needs a
// wider support for the same accuracy of the discrete sums.
struct WendlandC4 {
    static constexpr const char* name = "wendland_c4";
    // the lattice sum of x dW/dx is 0.999 in 2D at 2 dp (0.991 at 1.5 dp)
    static constexpr Real default_h_over_dp = Real(2);
    Real h = 0, alpha = 0, inv_h = 0;

    WendlandC4() = default;
    WendlandC4(Real h_, int dim) : h(h_), inv_h(1 / h_) {
        constexpr Real pi = 3.14159265358979323846;
        alpha = dim == 2 ? Real(9) / (4 * pi * h * h) : Real(495) / (256 * pi * h * h * h);
    }
    DF_HD Real support() const { return 2 * h; }
    DF_HD DF_HOT_INLINE Real w(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2) return 0;
        const Real t = 1 - Real(0.5) * q, t2 = t * t;
        return alpha * t2 * t2 * t2 * ((Real(35) / 12 * q + 3) * q + 1);
    }
    // (dW/dr) / r, so that grad W_ij = r_ij * grad_over_r(|r_ij|):
    // dW/dq = -(14/3) a_D q (1 - q/2)^5 (1 + 5q/2).
    DF_HD DF_HOT_INLINE Real grad_over_r(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2) return 0;
        const Real t = 1 - Real(0.5) * q, t2 = t * t;
        return -Real(14) / 3 * alpha * t2 * t2 * t * (1 + Real(2.5) * q) * inv_h * inv_h;
    }
};

} // namespace debrisflow::kernels
