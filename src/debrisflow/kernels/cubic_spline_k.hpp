#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/core/real.hpp"

namespace debrisflow::kernels {

// Cubic B-spline (Monaghan & Lattanzio 1985): W = a_D [1 - 3/2 q^2 + 3/4 q^3] (q < 1),
// a_D/4 (2 - q)^3 (1 <= q < 2); a_D = 10 / (7 pi h^2) in 2D, 1 / (pi h^3) in 3D.
struct CubicSpline {
    static constexpr const char* name = "cubic_spline";
    static constexpr Real default_h_over_dp = Real(1.7320508075688772); // sqrt(3)
    Real h = 0, alpha = 0, inv_h = 0;

    CubicSpline() = default;
    CubicSpline(Real h_, int dim) : h(h_), inv_h(1 / h_) {
        constexpr Real pi = 3.14159265358979323846;
        alpha = dim == 2 ? Real(10) / (7 * pi * h * h) : Real(1) / (pi * h * h * h);
    }
    DF_HD Real support() const { return 2 * h; }
    DF_HD DF_HOT_INLINE Real w(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2) return 0;
        if (q < 1) return alpha * (1 - Real(1.5) * q * q + Real(0.75) * q * q * q);
        const Real t = 2 - q;
        return alpha * Real(0.25) * t * t * t;
    }
    // (dW/dr) / r
    DF_HD DF_HOT_INLINE Real grad_over_r(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2 || r <= 0) return 0;
        if (q < 1) return alpha * (-3 + Real(2.25) * q) * inv_h * inv_h;
        const Real t = 2 - q;
        return -Real(0.75) * alpha * t * t * inv_h / r;
    }
};

} // namespace debrisflow::kernels
