// Hertz-Mindlin with JKR cohesion (Johnson, Kendall & Roberts 1971) against its closed forms:
// the loading curve F(delta) given parametrically by the contact radius a,
//   delta = a^2/R* - sqrt(2 pi w a / E*),  F = 4 E* a^3 / (3 R*) - sqrt(8 pi w E* a^3),
// the pull-off force 1.5 pi w R*, the separation delta_c = -(3/4) (pi^2 w^2 R*/E*^2)^(1/3)
// where the contact breaks, and the unloaded equilibrium a0^3 = 9 pi w R*^2 / (2 E*).
#include "debrisflow/dem/materials.hpp"
#include "dem_rig.hpp"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;
using test::DemRig;

namespace {

constexpr Real pi = 3.14159265358979323846;

dem::Material jkr_material(Real w, bool rigid = false) {
    dem::Material m;
    m.name = rigid ? "ceiling" : "clay";
    m.law = "hertz_mindlin_jkr";
    m.rigid = rigid;
    m.density = 2500;
    m.youngs_modulus = 1e7; // soft, as calibrated cohesive DEM materials are
    m.poisson = 0.3;
    m.restitution = 0.5;
    m.friction = 0.5;
    m.keys<dem::HertzMindlinJkrLaw>().work_of_adhesion = w;
    return m;
}

struct JkrCurve {
    Real e_star, w, r;
    Real delta(Real a) const { return a * a / r - std::sqrt(2 * pi * w * a / e_star); }
    Real force(Real a) const {
        return 4 * e_star * a * a * a / (3 * r) - std::sqrt(8 * pi * w * e_star * a * a * a);
    }
    Real pull_off_radius() const { return std::cbrt(9 * pi * w * r * r / (8 * e_star)); }
    Real critical_radius() const { return std::cbrt(pi * w * r * r / (8 * e_star)); }
    // contact radius on the stable branch (a > pull-off radius) where F = f (f > -1.5 pi w R)
    Real radius_at_force(Real f) const {
        Real lo = pull_off_radius(), hi = lo;
        while (force(hi) < f) hi *= 2;
        for (int it = 0; it < 200; ++it) {
            const Real mid = 0.5 * (lo + hi);
            (force(mid) < f ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }
};

} // namespace

// The law's elastic force (no approach rate) at the overlaps of the parametric curve, from the
// breaking point a_c to 3 a0, and its reach |delta_c|. Tolerance 1e-9 of the pull-off force
// (the law solves a quartic by Newton's method to round-off).
TEST(HertzMindlinJkr, ForceFollowsTheJkrCurveDownToTheBreakingPoint) {
    const Real w = 0.05, r = 0.002;
    const auto table = dem::build_pair_table({jkr_material(w)}, {}, "none");
    const dem::PairParams& p = table[0];
    const Real reff = r / 2, m = DemRig::sphere_mass(2500, r), meff = m / 2;
    const JkrCurve jkr{p.e_star, w, reff};
    const Real fc = 1.5 * pi * w * reff;
    const Real ac = jkr.critical_radius(),
               a0 = std::cbrt(9 * pi * w * reff * reff / (2 * p.e_star));
    Real least = 0;
    for (int k = 1; k <= 400; ++k) {
        const Real a = ac + (3 * a0 - ac) * Real(k) / 400;
        Real factor = 0;
        const dem::NormalResponse n =
            dem::normal_response(p, {jkr.delta(a), 0, reff, meff, std::sqrt(meff)}, 0, factor);
        ASSERT_NEAR(n.fn, jkr.force(a), 1e-9 * fc) << "a/a0 " << a / a0;
        least = std::min(least, n.fn);
    }
    // the most tensile force on the curve is the pull-off force (sampled: within 1e-4)
    EXPECT_NEAR(-least / fc, 1, 1e-4);
    const Real delta_c = -0.75 * std::cbrt(pi * pi * w * w * reff / (p.e_star * p.e_star));
    EXPECT_NEAR(dem::Laws::reach(p, reff) / -delta_c, 1, 1e-12);
    EXPECT_NEAR(jkr.delta(ac) / delta_c, 1, 1e-12); // the curve's own breaking point
    std::printf("JKR: F_c = %.4g N, delta_c = %.4g m, a0 = %.4g m\n", fc, delta_c, a0);
}

// With w = 0 the law is Hertz-Mindlin's, damping and tangential spring included (1e-12).
TEST(HertzMindlinJkr, WithoutAdhesionIsHertzMindlin) {
    dem::Material hertz = jkr_material(0);
    hertz.law = "hertz_mindlin";
    const auto tj = dem::build_pair_table({jkr_material(0)}, {}, "none");
    const auto th = dem::build_pair_table({hertz}, {}, "none");
    const Real reff = 0.001, meff = 1e-5;
    for (Real delta : {1e-7, 1e-6, 1e-5})
        for (Real rate : {-0.5, 0.0, 0.5}) {
            const dem::ContactInput c{delta, rate, reff, meff, std::sqrt(meff)};
            Real f1 = 0, f2 = 0;
            const auto a = dem::normal_response(tj[0], c, 0, f1);
            const auto b = dem::normal_response(th[0], c, 0, f2);
            EXPECT_NEAR(a.fn, b.fn, 1e-12 * std::abs(b.fn) + 1e-300) << delta << " " << rate;
            EXPECT_NEAR(a.kt, b.kt, 1e-12 * b.kt);
            EXPECT_NEAR(a.gt, b.gt, 1e-12 * b.gt);
            EXPECT_NEAR(a.friction, b.friction, 1e-12 * std::abs(b.friction) + 1e-300);
        }
}

namespace {

// A sphere hanging under a rigid adhesive ceiling (z = 0, normal -z) whose weight is `ratio`
// times the pull-off force 1.5 pi w r, released at rest at the overlap where the JKR force
// holds it (ratio < 1) or where it pulls hardest (ratio >= 1). Returns the gap below the
// ceiling after 0.05 s (negative: overlap), the gap it started at and the law's reach there.
struct Hanging {
    Real gap, start, reach;
};
Hanging hanging_gap(Real ratio) {
    const Real r = 0.001, g = 9.81, m = DemRig::sphere_mass(2500, r);
    const Real w = m * g / (1.5 * pi * r * ratio);
    DemRig rig;
    const dem::Material clay = jkr_material(w), ceiling = jkr_material(w, true);
    const auto table = dem::build_pair_table({clay, ceiling}, {}, "none");
    const JkrCurve jkr{table[1].e_star, w, r};
    const Real a = ratio < 1 ? jkr.radius_at_force(-m * g) : jkr.pull_off_radius();
    const Real delta = jkr.delta(a);
    rig.add_sphere({0, 0, -(r - delta)}, {}, r, 2500, 0);
    rig.add_plane("ceiling", {0, 0, 0}, {0, 0, -1}, 1);
    dem::DemParams p;
    p.gravity = {0, 0, -g};
    rig.start(p, {clay, ceiling}, {-0.01, -0.01, -0.01}, {0.01, 0.01, 0.01});
    const Real h = rig.solver->dt();
    for (Real t = 0; t < 0.05; t += h) rig.solver->advance(h);
    return {-rig.grains.pos[0].z - r, -delta, dem::Laws::reach(table[1], r)};
}

} // namespace

// Load control: the engine's contact loop (grain-wall, with the contact acting beyond touch)
// holds a weight of 0.98 F_c and lets 1.02 F_c fall, F_c = 1.5 pi w R* (JKR 1971): the
// pull-off force within 2 %. The held sphere stays at its equilibrium, a gap beyond touch
// (within 1 % of the reach), as the curve puts it.
TEST(HertzMindlinJkr, HoldsBelowThePullOffForceAndLetsGoAbove) {
    const Hanging held = hanging_gap(0.98), dropped = hanging_gap(1.02);
    std::printf("JKR hanging sphere: gap %.4g m (equilibrium %.4g m, reach %.3g m) at 0.98 F_c, "
                "%.3g m at 1.02 F_c\n",
                held.gap, held.start, held.reach, dropped.gap);
    EXPECT_NEAR(held.gap, held.start, 0.01 * held.reach); // still hanging where it was
    EXPECT_LT(held.gap, held.reach);
    EXPECT_GT(dropped.gap, 1e-3); // fell freely: 0.5 g t^2 = 12 mm
}

// Two spheres at rest a fraction of the reach apart in zero gravity snap together and come to
// rest at the unloaded JKR overlap delta0 = a0^2 / (3 R*), a0^3 = 9 pi w R*^2 / (2 E*)
// (grain-grain loop, contact formed beyond touch). Tolerance 1 % of delta0 (damped to rest).
TEST(HertzMindlinJkr, TwoSpheresSnapToTheUnloadedOverlap) {
    const Real r = 0.001, w = 0.05;
    const dem::Material clay = jkr_material(w);
    const auto table = dem::build_pair_table({clay}, {}, "none");
    const Real reff = r / 2, reach = dem::Laws::reach(table[0], reff);
    const Real a0 = std::cbrt(9 * pi * w * reff * reff / (2 * table[0].e_star));
    const Real delta0 = a0 * a0 / (3 * reff);
    DemRig rig;
    rig.add_sphere({-r - 0.25 * reach, 0, 0}, {}, r, 2500, 0);
    rig.add_sphere({r + 0.25 * reach, 0, 0}, {}, r, 2500, 0);
    dem::DemParams p;
    p.gravity = {0, 0, 0};
    rig.start(p, {clay}, {-0.01, -0.01, -0.01}, {0.01, 0.01, 0.01});
    const Real h = rig.solver->dt();
    for (Real t = 0; t < 0.02; t += h) rig.solver->advance(h);
    const Real delta = 2 * r - (rig.grains.pos[1].x - rig.grains.pos[0].x);
    std::printf("JKR pair at rest: overlap %.5g m (closed form %.5g m), reach %.3g m\n", delta,
                delta0, reach);
    EXPECT_NEAR(delta / delta0, 1, 0.01);
    EXPECT_LT(std::abs(rig.grains.vel[0].x), 1e-6);
}
