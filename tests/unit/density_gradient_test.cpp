// The renormalised density gradient (sph/density_gradient_k.hpp; Randles & Libersky 1996) is
// exact for a linear density field wherever the kernel is truncated (inside, at a free
// surface, in a corner), and with it Antuono et al.'s (2010) delta-SPH diffusion vanishes for
// any linear field, hydrostatic or not, where Molteni & Colagrossi's does not.
#include "debrisflow/kernels/wendland_c2_k.hpp"
#include "debrisflow/models/density_diffusion_k.hpp"
#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include "debrisflow/sph/density_gradient_k.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace debrisflow;

namespace {

constexpr Real dp = 0.01, h = 1.5 * dp;

// A block of n^dim fluid particles (x-z plane in 2D) whose density is the linear field
// rho0 + G.x (G not along gravity: a field Fourtakas's correction does not remove).
struct Block {
    int dim, n;
    Vec3 grad_field;
    particles::ParticleSet set;
    neighbors::CellGrid grid;
    kernels::WendlandC2 kernel;
    std::vector<Real> grad;

    Block(int dim_, int n_, Vec3 g) : dim(dim_), n(n_), grad_field(g), kernel(h, dim_) {
        const int ny = dim == 3 ? n : 1;
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < n; ++i) {
                    const Vec3 x{(i + Real(0.5)) * dp, dim == 3 ? (j + Real(0.5)) * dp : 0,
                                 (k + Real(0.5)) * dp};
                    set.add(x, {}, 1000 + dot(grad_field, x), 1000 * std::pow(dp, dim),
                            particles::Kind::fluid, 0);
                }
        const Real len = n * dp;
        grid.configure({0, 0, 0}, {len, dim == 3 ? len : 0, len}, 2 * h, dim,
                       {false, false, false});
        grid.build(set.x.data(), set.y.data(), set.z.data(), set.size());
        grad.assign(3 * std::size_t(set.size()), 0);
        const sph::RenormalisedDensityGradient<kernels::WendlandC2> op{set.view(), grid.view(),
                                                                       kernel, grad.data(), dim};
        for (Index i = 0; i < set.size(); ++i) op(i);
    }

    Index at(int i, int j, int k) const { return i + n * ((dim == 3 ? n * k : k) + j); }
    Vec3 pos(Index i) const { return {set.x[i], set.y[i], set.z[i]}; }
    Vec3 gradient(Index i) const { return {grad[3 * i], grad[3 * i + 1], grad[3 * i + 2]}; }

    // sum over i's neighbours of a diffusion model's rate D_i
    template <class D> Real diffusion_rate(const D& model, Index i) const {
        Real sum = 0;
        for (Index j = 0; j < set.size(); ++j) {
            if (j == i) continue;
            models::PairState s;
            s.r = pos(i) - pos(j);
            s.r2 = dot(s.r, s.r);
            if (s.r2 >= 4 * h * h) continue;
            s.f = kernel.grad_over_r(std::sqrt(s.r2));
            s.grad_w = s.f * s.r;
            s.rho_i = set.rho[i];
            s.rho_j = set.rho[j];
            s.vol_i = set.mass[i] / set.rho[i];
            s.vol_j = set.mass[j] / set.rho[j];
            s.inv_r2_eta2 = 1 / (s.r2 + Real(0.01) * h * h);
            s.grad_rho_i = gradient(i);
            s.grad_rho_j = gradient(j);
            sum += model.pair(s).i;
        }
        return sum;
    }
};

models::DiffusionContext context() {
    models::DiffusionContext c;
    c.h = h;
    c.c0 = 20;
    c.gravity = {0, 0, -9.81};
    return c;
}

void expect_gradient(const Block& b, Index i, const char* where) {
    const Vec3 g = b.gradient(i);
    const Real scale = std::sqrt(dot(b.grad_field, b.grad_field));
    // exact for a linear field: round-off only
    EXPECT_NEAR(g.x, b.grad_field.x, 1e-9 * scale) << where;
    EXPECT_NEAR(g.y, b.grad_field.y, 1e-9 * scale) << where;
    EXPECT_NEAR(g.z, b.grad_field.z, 1e-9 * scale) << where;
}

} // namespace

TEST(DensityGradient, RenormalisedGradientIsExactForALinearField2D) {
    const Block b(2, 12, {50, 0, -120});
    expect_gradient(b, b.at(6, 0, 6), "inside");
    expect_gradient(b, b.at(6, 0, 11), "free surface");
    expect_gradient(b, b.at(11, 0, 11), "corner");
    // the plain (unrenormalised) sum is not: at the surface it misses about half the kernel
    const Index top = b.at(6, 0, 11);
    Real acc[sph::density_gradient_sums<2>] = {};
    for (Index j = 0; j < b.set.size(); ++j) {
        const Vec3 r = b.pos(top) - b.pos(j);
        const Real r2 = dot(r, r);
        if (j == top || r2 >= 4 * h * h) continue;
        sph::add_density_gradient_pair<2>(
            acc, b.set.rho[j] - b.set.rho[top],
            b.set.mass[j] / b.set.rho[j] * b.kernel.grad_over_r(std::sqrt(r2)), r);
    }
    EXPECT_GT(std::abs(acc[1] - b.grad_field.z), 0.2 * std::abs(b.grad_field.z));
}

TEST(DensityGradient, RenormalisedGradientIsExactForALinearField3D) {
    const Block b(3, 8, {40, -70, 90});
    expect_gradient(b, b.at(4, 4, 4), "inside");
    expect_gradient(b, b.at(4, 4, 7), "free surface");
    expect_gradient(b, b.at(7, 7, 7), "corner");
}

// Antuono et al. (2010) eq. 5: psi_ji vanishes for a linear field, so D_i = 0 to round-off,
// at the free surface as inside; Molteni & Colagrossi's term does not (there it is of order
// delta h c0 |G| / h: the test would fail if the gradient term were dropped).
TEST(DensityGradient, AntuonoDiffusionVanishesForALinearField) {
    for (int dim : {2, 3}) {
        const Block b(dim, dim == 2 ? 12 : 8, {30, dim == 3 ? Real(20) : Real(0), -120});
        const auto antuono = models::Antuono::configure(context());
        const auto molteni = models::MolteniColagrossi::configure(context());
        const Index inside = b.at(b.n / 2, dim == 3 ? b.n / 2 : 0, b.n / 2);
        const Index surface = b.at(b.n / 2, dim == 3 ? b.n / 2 : 0, b.n - 1);
        const Real m = b.diffusion_rate(molteni, surface);
        EXPECT_GT(std::abs(m), 1e-3) << dim << "D"; // kg/m^3/s
        for (Index i : {inside, surface})
            EXPECT_LT(std::abs(b.diffusion_rate(antuono, i)), 1e-9 * std::abs(m))
                << dim << "D, particle " << i;
    }
}
