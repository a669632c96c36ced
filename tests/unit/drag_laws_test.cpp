// Drag laws of the unresolved SPH-DEM coupling (coupling/drag_laws_k.hpp).
#include "debrisflow/coupling/drag_laws_k.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;
using namespace debrisflow::coupling;

namespace {
constexpr Real pi = 3.14159265358979323846;
const Real d = 0.01, rho = 1000, mu = 1e-3;
Real stokes() {
    return 3 * pi * mu * d;
}
Real slip_for(Real re) {
    return re * mu / (rho * d);
}
} // namespace

// Stokes (1851) limit: beta -> 3 pi mu d as Re -> 0; Di Felice's Dallavalle C_d gives
// 24 -> 23.04 / Re there, i.e. 0.96 of Stokes, and a dense bed raises it by eps^(1 - 3.7).
TEST(DragLaws, StokesLimit) {
    EXPECT_NEAR(SchillerNaumann::beta({d, rho, mu, 0, 1}) / stokes(), 1, 1e-12);
    EXPECT_NEAR(DiFelice::beta({d, rho, mu, 0, 1}) / stokes(), 0.96, 1e-12);
    EXPECT_NEAR(DiFelice::beta({d, rho, mu, 0, 0.5}) / stokes(), 0.96 * std::pow(0.5, -2.7), 1e-9);
}

// At finite Re both laws follow their drag coefficients: F = C_d (pi d^2/8) rho |w| w, with
// Schiller-Naumann C_d = 24/Re (1 + 0.15 Re^0.687) and Dallavalle C_d = (0.63 + 4.8/sqrt Re)^2.
TEST(DragLaws, DragCoefficients) {
    for (Real re : {0.1, 1.0, 10.0, 100.0, 500.0}) {
        const Real w = slip_for(re), area = pi * d * d / 8 * rho * w;
        const Real sn = 24 / re * (1 + 0.15 * std::pow(re, 0.687));
        EXPECT_NEAR(SchillerNaumann::beta({d, rho, mu, w, 1}) / (sn * area), 1, 1e-12) << re;
        const Real dv = std::pow(0.63 + 4.8 / std::sqrt(re), 2);
        EXPECT_NEAR(DiFelice::beta({d, rho, mu, w, 1}) / (dv * area), 1, 1e-12) << re;
    }
    // Newton regime of Schiller-Naumann: C_d = 0.44
    const Real w = slip_for(2000);
    EXPECT_NEAR(SchillerNaumann::beta({d, rho, mu, w, 1}) / (0.44 * pi * d * d / 8 * rho * w), 1,
                1e-12);
}

// Di Felice's exponent chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2): 3.05 at Re = 10^1.5.
TEST(DragLaws, DiFeliceVoidageExponent) {
    const Real re = std::pow(10.0, 1.5), eps = 0.6;
    const Real w = slip_for(re) / eps; // Re uses the superficial slip eps |u - v|
    const Real ratio =
        DiFelice::beta({d, rho, mu, w, eps}) / DiFelice::beta({d, rho, mu, w * eps, 1});
    EXPECT_NEAR(ratio, std::pow(eps, 1 - 3.05), 1e-9); // at equal Re: eps^(1 - chi)
}
