// Kernels: normalisation (integral of W = 1), gradient consistent with W, compact support.
#include "debrisflow/kernels/kernel.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

template <class K> double integral(const K& k, int dim, double h) {
    const double d = h / 40, r = 2 * h;
    double s = 0;
    const int n = int(r / d) + 1;
    for (int i = -n; i <= n; ++i)
        for (int j = (dim == 3 ? -n : 0); j <= (dim == 3 ? n : 0); ++j)
            for (int l = -n; l <= n; ++l) {
                const double x = i * d, y = j * d, z = l * d;
                s += k.w(std::sqrt(x * x + y * y + z * z));
            }
    return s * (dim == 3 ? d * d * d : d * d);
}

TEST(Kernel, WendlandIntegratesToOne) {
    for (int dim : {2, 3})
        EXPECT_NEAR(integral(kernels::WendlandC2(0.1, dim), dim, 0.1), 1.0, 2e-3);
}
TEST(Kernel, WendlandC4IntegratesToOne) {
    for (int dim : {2, 3})
        EXPECT_NEAR(integral(kernels::WendlandC4(0.1, dim), dim, 0.1), 1.0, 2e-3);
}
TEST(Kernel, CubicSplineIntegratesToOne) {
    for (int dim : {2, 3})
        EXPECT_NEAR(integral(kernels::CubicSpline(0.1, dim), dim, 0.1), 1.0, 2e-3);
}
template <class K> void check_gradient(const K& k) {
    for (double r = 0.01; r < 0.2; r += 0.013) {
        const double e = 1e-7;
        const double dwdr = (k.w(r + e) - k.w(r - e)) / (2 * e);
        EXPECT_NEAR(k.grad_over_r(r) * r, dwdr, 1e-5 * std::abs(k.alpha)) << r;
    }
    EXPECT_EQ(k.w(0.2), 0.0);
    EXPECT_EQ(k.grad_over_r(0.21), 0.0);
}
TEST(Kernel, GradientMatchesDerivative) {
    check_gradient(kernels::WendlandC2(0.1, 2));
    check_gradient(kernels::WendlandC2(0.1, 3));
    check_gradient(kernels::CubicSpline(0.1, 2));
    check_gradient(kernels::CubicSpline(0.1, 3));
    check_gradient(kernels::WendlandC4(0.1, 2));
    check_gradient(kernels::WendlandC4(0.1, 3));
}
TEST(Kernel, RegistryNames) {
    EXPECT_EQ(kernels::KernelRegistry::names(),
              (std::vector<std::string>{"wendland_c2", "cubic_spline", "wendland_c4"}));
    EXPECT_THROW(kernels::make_kernel("gaussian", 0.1, 2), std::invalid_argument);
}
