// Particle shifting of the delta-plus-SPH scheme (Sun, Colagrossi, Marrone & Zhang 2017, CMAME
// 315, eq. 13): after each step every fluid particle moves by
//   dr_i = -2 h U_max dt sum_j [1 + R (W_ij / W(dp))^n] grad_i W_ij V_j,   R = 0.2, n = 4
// (their delta u = -Ma (2h) c0 sum ..., times dt; the same magnitude as Skillen et al. 2013
// with A = 2), limited to |dr| <= U_max dt / 2. Near the free surface the shift would push
// particles out of the fluid: it is projected on the surface's tangent plane there and dropped
// for particles that are nearly isolated (spray). Surface particles are found by the divergence
// of position (Lind et al. 2012), div r = -sum_j V_j r_ij . grad_i W_ij (= dim inside the
// fluid), in place of Sun et al.'s eigenvalue of the renormalisation matrix; their outward
// normal is -grad C / |grad C|, and "near the surface" is within the kernel support of one.
// Velocities and densities are not corrected for the shift (quasi-Lagrangian, as in the paper).
#include "debrisflow/exec/pair_scatter.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <cmath>

namespace debrisflow::sph {

namespace {
constexpr Real tensile_r = Real(0.2); // R of eq. 13 (n = 4 is written out below)
// div r / dim: 0.62 (2D) and 0.67 (3D) on a flat surface of a lattice, 0.91 and 0.94 one row
// below it, 0.37 on a 2D corner (Wendland C2, h = 1.5 dp); 0.75 is Lind et al.'s 2D threshold.
constexpr Real surface_ratio = Real(0.75), spray_ratio = Real(0.35);

// Particle i's data for the shifting sums, loaded once per row.
struct ShiftSide {
    Vec3 x;
    Real vol;
    bool fluid;
};

DF_HD inline Real wrap_periodic(Real v, Real lo, Real hi, bool periodic) {
    if (!periodic) return v;
    const Real len = hi - lo;
    if (v >= hi) return v - len;
    if (v < lo) return v + len;
    return v;
}
} // namespace

void SphSolver::shift_particles(Real dt) {
    if (params_.shifting != "delta_plus") return;
    auto pv = set_.view();
    const Real u_max = std::sqrt(exec::max_of(pv.n, [=](Index i) {
        return pv.is_fluid(i) ? pv.vx[i] * pv.vx[i] + pv.vy[i] * pv.vy[i] + pv.vz[i] * pv.vz[i]
                              : Real(0);
    }));
    if (!(u_max > 0)) return;
    const auto gv = grid_.view();
    const Real support2 = support_ * support_;
    const Real coeff = 2 * params_.h * u_max * dt, limit = Real(0.5) * u_max * dt;
    const Real dim = Real(params_.dim);
    const Domain d = domain_;
    const std::size_t n = std::size_t(pv.n);
    shift_.resize(3 * n);
    shift_normal_.resize(3 * n);
    shift_ratio_.resize(n);
    Real *grad = shift_.data(), *normal = shift_normal_.data(), *ratio = shift_ratio_.data();
    const auto load = [=](Index i) {
        return ShiftSide{pv.pos(i), pv.mass[i] / pv.rho[i], pv.is_fluid(i)};
    };
    // 1. Per fluid particle: the weighted concentration gradient sum_j [1 + R q^n] V_j grad W_ij
    //    and div r / dim; each surface particle's outward normal -grad C / |grad C|.
    std::visit(
        [&](const auto& kernel) {
            const Real inv_w_dp = 1 / kernel.w(params_.dp);
            exec::for_each_pair_w<4>(
                list_, pv.n, buffers_, load,
                [=](const ShiftSide& a, Index, Index j, Real* acc_i, Real* out_j) {
                    const bool fj = pv.is_fluid(j);
                    if (!a.fluid && !fj) return;
                    const Vec3 r = gv.separation(a.x, pv.pos(j)); // x_i - x_j
                    const Real r2 = dot(r, r);
                    if (r2 >= support2) return;
                    const Real dist = std::sqrt(r2), f = kernel.grad_over_r(dist);
                    const Real q = kernel.w(dist) * inv_w_dp, q2 = q * q;
                    const Real weight = 1 + tensile_r * q2 * q2; // n = 4
                    if (a.fluid) { // grad_i W_ij = f r
                        const Real vol_j = pv.mass[j] / pv.rho[j];
                        acc_i[0] += weight * vol_j * f * r.x;
                        acc_i[1] += weight * vol_j * f * r.y;
                        acc_i[2] += weight * vol_j * f * r.z;
                        acc_i[3] -= vol_j * f * r2;
                    }
                    if (fj) { // grad_j W_ji = -f r
                        out_j[0] -= weight * a.vol * f * r.x;
                        out_j[1] -= weight * a.vol * f * r.y;
                        out_j[2] -= weight * a.vol * f * r.z;
                        out_j[3] -= a.vol * f * r2;
                    }
                },
                [=](Index i, const Real* total) {
                    for (int k = 0; k < 3; ++k) grad[3 * i + k] = total[k];
                    ratio[i] = total[3] / dim;
                    const Real g = std::sqrt(total[0] * total[0] + total[1] * total[1] +
                                             total[2] * total[2]);
                    const bool surface = pv.is_fluid(i) && ratio[i] < surface_ratio && g > 0;
                    for (int k = 0; k < 3; ++k) normal[3 * i + k] = surface ? -total[k] / g : 0;
                });
        },
        models_.kernel);
    // 2. Near the surface (a surface particle within the kernel support, or on it) the normal
    //    is the sum of those particles' normals; the shift keeps its tangential part only.
    exec::for_each_pair_w<3>(
        list_, pv.n, buffers_, load,
        [=](const ShiftSide& a, Index i, Index j, Real* acc_i, Real* out_j) {
            const bool fj = pv.is_fluid(j);
            if (!a.fluid || !fj) return;
            const Vec3 r = gv.separation(a.x, pv.pos(j));
            if (dot(r, r) >= support2) return;
            for (int k = 0; k < 3; ++k) {
                acc_i[k] += normal[3 * j + k];
                out_j[k] += normal[3 * i + k];
            }
        },
        [=](Index i, const Real* total) {
            Vec3 dr{};
            if (pv.is_fluid(i) && ratio[i] >= spray_ratio) {
                dr = -coeff * Vec3{grad[3 * i], grad[3 * i + 1], grad[3 * i + 2]};
                const Vec3 m{total[0] + normal[3 * i], total[1] + normal[3 * i + 1],
                             total[2] + normal[3 * i + 2]};
                const Real m2 = dot(m, m);
                if (m2 > 0) dr = dr - (dot(dr, m) / m2) * m;
                const Real len = norm(dr);
                if (len > limit) dr = (limit / len) * dr;
            }
            // grad of particle i is read only here: it takes the shift
            grad[3 * i] = dr.x;
            grad[3 * i + 1] = dr.y;
            grad[3 * i + 2] = dr.z;
        });
    exec::for_each(pv.n, [=](Index i) {
        if (!pv.is_fluid(i)) return;
        pv.x[i] = wrap_periodic(pv.x[i] + grad[3 * i], d.lo.x, d.hi.x, d.periodic[0]);
        pv.y[i] = wrap_periodic(pv.y[i] + grad[3 * i + 1], d.lo.y, d.hi.y, d.periodic[1]);
        pv.z[i] = wrap_periodic(pv.z[i] + grad[3 * i + 2], d.lo.z, d.hi.z, d.periodic[2]);
    });
}

} // namespace debrisflow::sph
