#include "debrisflow/dem/materials.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/contact_laws_k.hpp"
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace debrisflow::dem {

Real linear_damping_ratio(Real e) {
    if (e >= 1) return 0;
    const Real l = std::log(e), pi = 3.14159265358979323846;
    return -l / std::sqrt(pi * pi + l * l);
}

Real tsuji_restitution(Real alpha) {
    // X(0) = 0, X'(0) = 1; RK4 on (X, V) until the clamped force vanishes while separating.
    auto acc = [alpha](Real x, Real v) {
        const Real xp = x > 0 ? x : 0;
        const Real f = -xp * std::sqrt(xp) - alpha * std::sqrt(std::sqrt(xp)) * v;
        return f < 0 ? f : Real(0); // no tension
    };
    Real x = 0, v = 1;
    const Real h = 2e-4;
    for (int step = 0; step < 200000; ++step) {
        const Real k1x = v, k1v = acc(x, v);
        const Real k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const Real k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const Real k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (v < 0 && (x <= 0 || acc(x, v) == 0)) return -v;
    }
    return 0;
}

Real tsuji_alpha(Real e) {
    if (e >= 1) return 0;
    if (!(e >= hertz_min_restitution))
        throw InputError(fmt::format("restitution {} of a hertz_mindlin pair is below {}: the "
                                     "Tsuji damping is that of an overdamped contact there",
                                     e, hertz_min_restitution));
    // e(alpha) falls monotonically: e(64) = 3e-4 < hertz_min_restitution, so hi stays <= 64.
    Real lo = 0, hi = 1;
    while (tsuji_restitution(hi) > e && hi < 64) hi *= 2;
    for (int it = 0; it < 50; ++it) {
        const Real mid = 0.5 * (lo + hi);
        (tsuji_restitution(mid) > e ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

namespace {

Real combine_spring(Real a, Real b) {
    if (a <= 0) return b;
    if (b <= 0) return a;
    return 2 * a * b / (a + b);
}

Real shear_compliance(const Material& m) {
    return m.rigid ? 0 : 2 * (2 - m.poisson) * (1 + m.poisson) / m.youngs_modulus;
}

} // namespace

Real hertz_compliance(const Material& m) {
    return m.rigid ? 0 : (1 - m.poisson * m.poisson) / m.youngs_modulus;
}

std::vector<PairParams> build_pair_table(const std::vector<Material>& mats,
                                         const std::vector<PairOverride>& overrides,
                                         const std::string& rolling) {
    const std::size_t n = mats.size();
    std::vector<PairParams> table(n * n);
    const RollingId roll = rolling == "constant_torque" ? RollingId::constant_torque
                           : rolling == "epsd"          ? RollingId::epsd
                                                        : RollingId::none;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const Material &a = mats[i], &b = mats[j];
            const PairOverride* o = nullptr;
            for (const auto& ov : overrides)
                if ((ov.a == a.name && ov.b == b.name) || (ov.a == b.name && ov.b == a.name))
                    o = &ov;
            std::string law = o && o->law ? *o->law : a.law;
            PairParams p;
            p.rolling = roll;
            p.restitution =
                o && o->restitution ? *o->restitution : 0.5 * (a.restitution + b.restitution);
            p.mu = o && o->friction ? *o->friction : 0.5 * (a.friction + b.friction);
            p.mu_roll = o && o->rolling_friction ? *o->rolling_friction
                                                 : 0.5 * (a.rolling_friction + b.rolling_friction);
            p.kn = o && o->kn ? *o->kn : combine_spring(a.kn, b.kn);
            p.kt = o && o->kt ? *o->kt : combine_spring(a.kt, b.kt);
            const Real ce = hertz_compliance(a) + hertz_compliance(b),
                       cg = shear_compliance(a) + shear_compliance(b);
            p.e_star = ce > 0 ? 1 / ce : 0;
            p.g_star = cg > 0 ? 1 / cg : 0;
            if (law == LinearLaw::name) {
                p.law = LawId::linear;
                p.set_linear_damping(linear_damping_ratio(p.restitution));
            } else if (law == HertzMindlinLaw::name) {
                p.law = LawId::hertz_mindlin;
                p.damping = tsuji_alpha(p.restitution);
            } else {
                p.law = LawId::dcdem;
                p.damping =
                    o && o->damping_cn ? *o->damping_cn : 0.5 * (a.damping_cn + b.damping_cn);
            }
            table[i * n + j] = p;
        }
    return table;
}

} // namespace debrisflow::dem
