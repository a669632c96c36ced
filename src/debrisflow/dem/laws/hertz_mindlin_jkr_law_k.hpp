#pragma once
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/laws/hertz_time.hpp"
#include "debrisflow/dem/laws/law_types_k.hpp"
#include "debrisflow/dem/tsuji_damping.hpp"
#include <cmath>
#include <optional>

namespace debrisflow::dem {

// Hertz-Mindlin with JKR cohesion (Johnson, Kendall & Roberts 1971), for wet and clayey
// debris: the contact radius a follows from the overlap by delta = a^2/R* - sqrt(2 pi w a/E*)
// and F_n = 4 E* a^3/(3 R*) - sqrt(8 pi w E* a^3), w the work of adhesion [J/m^2] (the
// energy per unit area to part the two surfaces; 2 gamma for one surface energy gamma). The
// force is tensile down to delta_c = -(3/4) (pi^2 w^2 R*/E*^2)^(1/3), where a = a_c and the
// contact breaks; under load control it pulls off at 1.5 pi w R*. As in EDEM, the curve acts
// on approach as on release (attraction from delta_c on, no hysteresis). Damping and
// tangential spring are Hertz-Mindlin's taken at the contact radius (k_h sqrt(delta) ->
// (4/3) E* a, k_t = 8 G* a; alpha(e) of the Hertz oscillator); the damped force is not let
// below the elastic one's attraction (w = 0 is Hertz-Mindlin exactly). Sliding starts at
// mu (F_n + 2 F_c), F_c = 1.5 pi w R* (Thornton & Yin 1991).
// law_constant[0] = w; law_constant[1] = c0 = sqrt(2 pi w / E*).
struct HertzMindlinJkrLaw {
    static constexpr const char* name = "hertz_mindlin_jkr";
    static constexpr Stiffness stiffness = Stiffness::moduli;
    static constexpr Real min_restitution = hertz_min_restitution;
    static constexpr bool uses_restitution = true;
    static constexpr Real pi = Real(3.14159265358979323846);

    // Material key: work_of_adhesion w [J/m^2], required on a material of this law; a pair's
    // is the geometric mean of its materials' (w_12 = 2 sqrt(gamma_1 gamma_2)) unless a
    // [[contact]] gives it.
    struct MaterialKeys {
        Real work_of_adhesion = 0;
    };
    template <class Table> static MaterialKeys read_keys(const Table& t, bool own) {
        MaterialKeys k;
        if (own || t.has("work_of_adhesion")) k.work_of_adhesion = t.real("work_of_adhesion");
        if (!(k.work_of_adhesion >= 0)) t.fail("work_of_adhesion", "must be >= 0 [J/m^2]");
        return k;
    }
    template <class Table> static std::optional<MaterialKeys> read_override(const Table& t) {
        if (!t.has("work_of_adhesion")) return std::nullopt;
        return read_keys(t, true);
    }
    static void configure(PairParams& p, const MaterialKeys& a, const MaterialKeys& b,
                          const std::optional<MaterialKeys>& pair) {
        const Real w =
            pair ? pair->work_of_adhesion : std::sqrt(a.work_of_adhesion * b.work_of_adhesion);
        p.damping = tsuji_alpha(p.restitution);
        p.law_constant[0] = w;
        p.law_constant[1] = p.e_star > 0 ? std::sqrt(2 * pi * w / p.e_star) : 0;
    }

    // Square root x = sqrt(a) of the contact radius at overlap delta: the root of
    // x^4 - R* c0 x - R* delta = 0 on the stable branch x >= x_c = (R* c0 / 4)^(1/3), by
    // Newton's method from x0 = (R* max(delta, 0))^(1/4) + (R* c0)^(1/3) >= root (the
    // quartic is convex there, so the iterates fall monotonically onto the root).
    DF_HD static Real root_contact_radius(Real delta, Real r_eff, Real c0) {
        const Real rd = r_eff * (delta > 0 ? delta : Real(0));
        if (c0 == 0) return std::sqrt(std::sqrt(rd));
        const Real rc = r_eff * c0;
        Real x = std::sqrt(std::sqrt(rd)) + std::cbrt(rc);
        for (int it = 0; it < 64; ++it) {
            const Real x3 = x * x * x;
            const Real slope = 4 * x3 - rc;
            if (!(slope > 0)) break; // at the critical point
            const Real step = (x3 * x - rc * x - r_eff * delta) / slope;
            if (!(step > Real(1e-15) * x)) break;
            x -= step;
        }
        const Real xc = std::cbrt(Real(0.25) * rc);
        return x > xc ? x : xc;
    }

    DF_HD static NormalResponse normal(const PairParams& p, const ContactInput& c) {
        const Real c0 = p.law_constant[1];
        const Real x = root_contact_radius(c.delta, c.r_eff, c0);
        const Real a = x * x, x3 = a * x;
        const Real fe = Real(4) / 3 * p.e_star * x3 * x3 / c.r_eff - 2 * p.e_star * c0 * x3;
        const Real gn = p.damping * c.sqrt_m_eff * std::sqrt(Real(4) / 3 * p.e_star * a);
        Real fn = fe + gn * c.ddelta;
        const Real floor = fe < 0 ? fe : Real(0);
        fn = fn > floor ? fn : floor;
        const Real kt = 8 * p.g_star * a;
        const Real gt = p.damping * c.sqrt_m_eff * std::sqrt(Real(2) / 3 * kt);
        const Real load = fn + 3 * pi * p.law_constant[0] * c.r_eff; // F_n + 2 F_c
        return {fn, kt, gt, p.mu * (load > 0 ? load : Real(0)), 2 * p.e_star * a};
    }
    DF_HD static Real friction_factor(Real) { return 1; }
    // |delta_c| = (3/4) (pi^2 w^2 R*/E*^2)^(1/3) = (3/4) (c0^4 R*/4)^(1/3).
    DF_HD static Real reach(const PairParams& p, Real r_eff) {
        const Real c0 = p.law_constant[1];
        return Real(0.75) * std::cbrt(Real(0.25) * c0 * c0 * c0 * c0 * r_eff);
    }

    static constexpr bool speed_dependent_time = true;
    static Real undamped_contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return hertz_contact_time(p, m_eff, r_eff, v);
    }
    static Real contact_time(const PairParams& p, Real m_eff, Real r_eff, Real v) {
        return hertz_contact_time(p, m_eff, r_eff, v);
    }
    // Tsuji as in hertz_mindlin: g_n = alpha sqrt(m* 4/3 E* a) against the tangent 2 E* a, and
    // g_t = alpha sqrt(2/3 k_t m*): both alpha sqrt(2/3) / 2
    static DampingRatios damping_ratios(const PairParams& p) {
        const Real z = p.damping * Real(0.40824829046386301636);
        return {z, z};
    }
    // Mindlin k_t = 8 G* a against the Hertz tangent 2 E* a.
    static Real tangential_ratio(const PairParams& p) {
        return p.e_star > 0 ? 4 * p.g_star / p.e_star : 0;
    }
};

} // namespace debrisflow::dem
