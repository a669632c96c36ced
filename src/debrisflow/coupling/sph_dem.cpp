#include "debrisflow/coupling/sph_dem.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/kernels/kernel.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace debrisflow::coupling {

namespace {
constexpr Real pi = 3.14159265358979323846;
// Below this fluid share a grain is taken as out of the fluid.
constexpr Real dry_share = 1e-3;

// Solves L g = b (Cramer's rule); returns b itself when L is close to singular (a grain
// with few neighbours), where the plain kernel gradient is the better estimate.
Vec3 solve3(const Real L[3][3], Vec3 b) {
    const Real det = L[0][0] * (L[1][1] * L[2][2] - L[1][2] * L[2][1]) -
                     L[0][1] * (L[1][0] * L[2][2] - L[1][2] * L[2][0]) +
                     L[0][2] * (L[1][0] * L[2][1] - L[1][1] * L[2][0]);
    if (!(std::abs(det) > Real(0.05))) return b;
    Vec3 g;
    for (int c = 0; c < 3; ++c) {
        Real m[3][3];
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) m[r][k] = k == c ? b[r] : L[r][k];
        g[c] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
               det;
    }
    return g;
}
} // namespace

SphDemCoupling::SphDemCoupling(sph::SphSolver& fluid, dem::DemSolver& dem, std::string drag_law)
    : fluid_(fluid), dem_(dem), drag_law_(std::move(drag_law)) {
    if (!DragRegistry::has(drag_law_))
        throw InputError("unknown drag law \"" + drag_law_ + "\" (" + DragRegistry::choices() +
                         ")");
    if (fluid_.params().dim != 3 || dem_.params().dim != 3)
        throw InputError("the SPH-DEM drag coupling is 3D only (sphere drag laws)");
    dem_.attach_fluid(&load_);
}

time::DtLimit SphDemCoupling::stable_dt() const {
    return {std::numeric_limits<Real>::max(), "none"};
}

std::vector<Exchange> SphDemCoupling::exchanges() const {
    return {{"sph", "dem",
             "fluid pressure gradient, velocity, density and viscosity at the grains, as their "
             "fluid load (dem::FluidLoad: held force, drag rate beta, fluid velocity)",
             When::force_evaluation},
            {"dem", "sph",
             "the fluid load's impulse over the DEM's last advance / dt, to the fluid particles' "
             "accelerations with weights V_j W_ij / S_f",
             When::force_evaluation}};
}

void SphDemCoupling::compute_forces() {
    ScopedTimer timer(t_forces_);
    const std::size_t n = std::size_t(dem_.grains().size());
    load_.resize(n);
    if (load_.time > 0) {
        for (std::size_t i = 0; i < n; ++i) {
            load_.handover[i] = load_.impulse[i];
            load_.impulse[i] = {};
        }
        load_.time = 0;
    }
    if (n == 0) return;
    interpolate();
    apply_reaction();
}

void SphDemCoupling::interpolate() {
    const auto& sp = fluid_.params();
    const Real support = fluid_.support();
    const Domain& dom = fluid_.domain();
    particles::ParticleSet& set = fluid_.particles();
    const Index np = set.size();
    fluid_grid_.configure(dom.lo, dom.hi, support, 3, dom.periodic);
    fluid_grid_.build(set.x.data(), set.y.data(), set.z.data(), np);
    dem::GrainSet& grains = dem_.grains();
    const Index ng = grains.size();
    grain_grid_.configure(dom.lo, dom.hi, support, 3, dom.periodic);
    const Real* gp = &grains.pos[0].x;
    grain_grid_.build(gp, gp + 1, gp + 2, ng, 3);
    share_.assign(std::size_t(ng), 0);

    const particles::ParticleView pv = set.view();
    const dem::GrainView g = grains.view();
    const neighbors::GridView fgrid = fluid_grid_.view(), ggrid = grain_grid_.view();
    const bool has_mu = set.mu.size() == std::size_t(np);
    const Real nu = sp.nu;
    Vec3* lf = load_.force.data();
    Vec3* lu = load_.u.data();
    Real* lb = load_.beta.data();
    Real* share = share_.data();
    Real max_rate = 0;
    const std::string law = drag_law_;
    std::visit(
        [&](const auto& kernel_model) {
            // A copy captured by value: clang 14 rejects the enclosing generic lambda's
            // parameter inside the nested lambdas below.
            const auto kernel = kernel_model;
            DragRegistry::visit_name(law, [&, kernel]<class Drag>() {
                // per grain: its fluid load; the largest drag rate beta / m over the grains
                max_rate = exec::max_of(ng, [&](Index i) -> Real {
                    const Vec3 xi = g.pos[i];
                    // One pass gathers the kernel sums and, for the renormalised pressure
                    // gradient (Bonet & Lok 1999), A = sum_j V_j p_j grad W_ij,
                    // B = sum_j V_j grad W_ij and L = sum_j V_j (x_j - x_i) (x) grad W_ij;
                    // then grad p = L^-1 (A - p_i B) = L^-1 sum_j V_j (p_j - p_i) grad W_ij with
                    // p_i the Shepard pressure: exact for a linear (hydrostatic) field, where
                    // the plain sum A errs by p_i B on a compressed lattice.
                    Real sf = 0, sb = 0, mass = 0, mu = 0, sp = 0;
                    Vec3 mom{}, ga{}, gb{};
                    Real L[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
                    fgrid.for_each_neighbor(-1, xi, pv.x, pv.y, pv.z,
                                            [&](Index j, Vec3 r, Real r2) {
                                                const Real d = std::sqrt(r2);
                                                const Real w = kernel.w(d);
                                                const Real vj = pv.mass[j] / pv.rho[j];
                                                // grad_i W(x_i - x_j) = r (dW/dr) / |r|
                                                const Vec3 gw = (vj * kernel.grad_over_r(d)) * r;
                                                ga += pv.p[j] * gw;
                                                gb += gw;
                                                for (int a = 0; a < 3; ++a)
                                                    for (int b = 0; b < 3; ++b)
                                                        L[a][b] -= gw[a] * r[b];
                                                sp += vj * pv.p[j] * w;
                                                if (!pv.is_fluid(j)) {
                                                    sb += vj * w;
                                                    return;
                                                }
                                                sf += vj * w;
                                                mass += pv.mass[j] * w;
                                                mom += (vj * w) * pv.vel(j);
                                                if (has_mu) mu += vj * w * pv.mu[j];
                                            });
                    if (sf < dry_share) {
                        lf[i] = {}, lu[i] = {}, lb[i] = 0;
                        return 0;
                    }
                    share[i] = sf;
                    const Real p_i = sp / (sf + sb);
                    const Vec3 gsum = ga - p_i * gb;
                    const Vec3 gradp = solve3(L, gsum);
                    Real solid = 0;
                    ggrid.for_each_neighbor(
                        -1, xi, gp, gp + 1, gp + 2,
                        [&](Index k, Vec3, Real r2) {
                            const Real rk = g.radius[k];
                            solid += Real(4) / 3 * pi * rk * rk * rk * kernel.w(std::sqrt(r2));
                        },
                        3);
                    const Real eps = std::clamp(1 - solid, Real(0.2), Real(1));
                    const Real rho_f = mass / sf;
                    const Vec3 u = (1 / sf) * mom;
                    const Real mu_f = has_mu && mu > 0 ? mu / sf : rho_f * nu;
                    const Real phi = std::min(Real(1), sf / (1 - std::min(sb, Real(0.9))));
                    const Real r = g.radius[i];
                    const Real vol = Real(4) / 3 * pi * r * r * r;
                    const Real slip = norm(u - g.vel[i]);
                    const Real beta = phi * Drag::beta({2 * r, rho_f, mu_f, slip, eps});
                    lf[i] = (-phi * vol) * gradp;
                    lu[i] = u;
                    lb[i] = beta;
                    return beta * g.inv_mass[i];
                });
            });
        },
        fluid_.models().kernel);
    load_.max_rate = max_rate;
}

void SphDemCoupling::apply_reaction() {
    if (step_dt_ <= 0) return; // before the first step: nothing to hand over
    particles::ParticleSet& set = fluid_.particles();
    const particles::ParticleView pv = set.view();
    const dem::GrainView g = dem_.grains().view();
    const neighbors::GridView ggrid = grain_grid_.view();
    const Index ng = g.n;
    // Grain i hands fluid particle j the force -F_i V_j W_ij / S_f (the weights sum to one),
    // F_i = impulse / dt the mean fluid force on the grain; per unit fluid mass that is
    // W_ij c_i / rho_j with c_i = -F_i / S_f.
    reaction_.assign(std::size_t(ng), Vec3{});
    const Vec3* handover = load_.handover.data();
    const Real inv_dt = 1 / step_dt_;
    for (Index i = 0; i < ng; ++i)
        if (share_[i] > 0) reaction_[i] = (-inv_dt / share_[i]) * handover[i];
    const Vec3* c = reaction_.data();
    const Real* gp = &g.pos[0].x;
    // Gathered per fluid particle over the grains around it (the grain grid from
    // interpolate()): no write conflicts, and the sums do not depend on the thread count.
    std::visit(
        [&](const auto& kernel) {
            exec::for_each(pv.n, [&](Index j) {
                if (!pv.is_fluid(j)) return;
                Vec3 a{};
                ggrid.for_each_neighbor(
                    -1, pv.pos(j), gp, gp + 1, gp + 2,
                    [&a, &kernel, c](Index i, Vec3, Real r2) {
                        a += kernel.w(std::sqrt(r2)) * c[i];
                    },
                    3);
                if (a.x == 0 && a.y == 0 && a.z == 0) return;
                const Real inv_rho = 1 / pv.rho[j];
                pv.ax[j] += inv_rho * a.x;
                pv.ay[j] += inv_rho * a.y;
                pv.az[j] += inv_rho * a.z;
            });
        },
        fluid_.models().kernel);
}

} // namespace debrisflow::coupling
