#include "debrisflow/dem/critical_dt.hpp"
#include "debrisflow/dem/contact_time.hpp"
#include "debrisflow/dem/rolling_models_k.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::dem {

time::DtLimit critical_dt(const GrainSet& grains, const std::vector<int>& wall_materials,
                          const std::vector<Material>& materials,
                          const std::vector<PairParams>& table, const DemParams& params,
                          const Domain& domain, Real safety, const ObstacleSet* obstacles) {
    const Index n = grains.size();
    const int nm = int(materials.size());
    if (n == 0) return {std::numeric_limits<Real>::max(), "no grains"};
    std::vector<Real> mmin(std::size_t(nm), std::numeric_limits<Real>::max()), rmin = mmin;
    // Per material, the largest tangential compliance of a contact point, 1/m + r^2/I (3.5/m
    // for a sphere, 3/m for a disc), and the largest rotational one, 1/I. A clump member's
    // contact point sits at up to |s| + r from the clump's centre of mass (s: the member's
    // offset), so its compliances are 1/M + |s|^2/I_min (normal; the mass it stands for is the
    // inverse) and 1/M + (|s| + r)^2/I_min (tangential), with the clump's mass M and smallest
    // principal moment I_min.
    std::vector<Real> ct(std::size_t(nm), 0), cr = ct;
    const ClumpSet& clumps = grains.clumps;
    std::vector<std::pair<std::int32_t, std::uint32_t>> member_of; // id -> (clump, member)
    if (!clumps.empty()) {
        member_of.assign(grains.next_id(), {-1, 0});
        for (Index c = 0; c < clumps.size(); ++c)
            for (std::uint32_t k = clumps.first[std::size_t(c)];
                 k < clumps.first[std::size_t(c) + 1]; ++k)
                member_of[clumps.member_id[k]] = {std::int32_t(c), k};
    }
    Real vmax = 0;
    for (Index i = 0; i < n; ++i) {
        const std::size_t k = std::size_t(i), m = grains.material[k];
        const Real r = grains.radius[k];
        Real normal = grains.inv_mass[k], tangential = normal + r * r * grains.inv_inertia[k],
             rotational = grains.inv_inertia[k];
        if (!member_of.empty() && member_of[grains.id[k]].first >= 0) {
            const auto [c, slot] = member_of[grains.id[k]];
            const Real inv_m = 1 / clumps.mass[std::size_t(c)];
            const Real inv_i = clumps.max_inv_inertia(c), lever = norm(clumps.offset[slot]);
            normal = inv_m + lever * lever * inv_i;
            tangential = inv_m + (lever + r) * (lever + r) * inv_i;
            rotational = inv_i;
        }
        mmin[m] = std::min(mmin[m], 1 / normal);
        rmin[m] = std::min(rmin[m], r);
        ct[m] = std::max(ct[m], tangential);
        cr[m] = std::max(cr[m], rotational);
        vmax = std::max(vmax, norm(grains.vel[k]));
    }
    Real vref = params.reference_velocity;
    if (vref <= 0) {
        const Real height = domain.hi.z - domain.lo.z;
        vref = std::max({vmax, std::sqrt(2 * norm(params.gravity) * height), Real(1)});
    }
    const Real pi = 3.14159265358979323846;
    time::DtLimit best{std::numeric_limits<Real>::max(), ""};
    auto consider = [&](Real dt, std::string why) {
        if (dt < best.dt) best = {dt, std::move(why)};
    };
    std::vector<int> partners; // grain materials, wall materials, and "own" (-1)
    for (int a = 0; a < nm; ++a)
        if (mmin[std::size_t(a)] < std::numeric_limits<Real>::max()) partners.push_back(a);
    const std::size_t grain_partners = partners.size();
    for (int m : wall_materials) partners.push_back(m);
    const std::size_t wall_partners = partners.size();
    // Rigid bodies' contact spheres, per material: the most compliant sphere of a free body
    // (its compliances add to the grain's, as a second grain's would) and the smallest radius.
    struct BodySide {
        Real normal = 0, tangential = 0, rotational = 0, r = std::numeric_limits<Real>::max();
    };
    std::vector<BodySide> body(static_cast<std::size_t>(nm), BodySide{});
    if (obstacles)
        for (const auto& o : obstacles->spheres) {
            if (o.material < 0 || o.material >= nm) continue;
            BodySide& b = body[std::size_t(o.material)];
            b.normal = std::max(b.normal, o.normal_compliance);
            b.tangential = std::max(b.tangential, o.tangential_compliance);
            b.rotational = std::max(b.rotational, o.rotational_compliance);
            b.r = std::min(b.r, o.r);
        }
    for (int m = 0; m < nm; ++m)
        if (body[std::size_t(m)].normal > 0) partners.push_back(m);
    for (int a = 0; a < nm; ++a) {
        if (mmin[std::size_t(a)] == std::numeric_limits<Real>::max()) continue;
        const Material& ma = materials[std::size_t(a)];
        for (std::size_t k = 0; k < partners.size(); ++k) {
            const int b = partners[k] < 0 ? a : partners[k];
            const bool on_body = k >= wall_partners;
            const bool wall = k >= grain_partners && !on_body;
            const PairParams& p = table[std::size_t(a * nm + b)];
            const Real m1 = mmin[std::size_t(a)], r1 = rmin[std::size_t(a)];
            // the partner's compliances: none (a wall), a grain's, or a body sphere's
            const BodySide& bs = body[std::size_t(b)];
            const Real r2 = on_body ? bs.r : rmin[std::size_t(b)];
            const Real meff = wall      ? m1
                              : on_body ? 1 / (1 / m1 + bs.normal)
                                        : m1 * mmin[std::size_t(b)] / (m1 + mmin[std::size_t(b)]);
            const Real reff = wall ? r1 : r1 * r2 / (r1 + r2);
            const std::string pair = ma.name + "-" +
                                     (wall      ? std::string("wall")
                                      : on_body ? "body (" + materials[std::size_t(b)].name + ")"
                                                : materials[std::size_t(b)].name);
            // The contact's other modes, relative to its normal one (frequency ratios): the
            // tangential spring k_t acting on the contact point's compliance 1/m + r^2/I of
            // each side, and the EPSD rolling spring k_r = 2.25 k_n mu_r^2 R*^2 acting on 1/I
            // of each side (Iwashita & Oda 1998; Ai et al. 2011, eq. 13).
            const Real c_t = ct[std::size_t(a)] + (wall      ? 0
                                                   : on_body ? bs.tangential
                                                             : ct[std::size_t(b)]);
            const Real c_r = cr[std::size_t(a)] + (wall      ? 0
                                                   : on_body ? bs.rotational
                                                             : cr[std::size_t(b)]);
            const Real rolling_ratio = RollingRegistry::visit_index(
                p.rolling, [&]<class M>() { return M::mode_ratio(p, reff, c_r, meff); });
            // tc_normal: the undamped normal contact time; the other modes' times are taken
            // undamped too (their damping ratios differ from the normal one, and undamped is the
            // conservative bound).
            //
            // A dashpot g on a mode of frequency w (damping ratio zeta = g / (2 sqrt(k m))) is
            // integrated explicitly, which is stable for dt < 2 m / g = 1 / (zeta w) per contact
            // (the spring's bound is 2 / w); a grain's contacts add their dashpots on its spin
            // and motion. It gets the same margin as the spring: dt <= safety x (pi / 2) x
            // 1 / (zeta w) = safety x t_c / (2 zeta), t_c = pi / w the mode's undamped time.
            // It limits once zeta > 1/2: the tangential dashpot of a low-restitution pair, on
            // the contact point's compliance, is sqrt(3) (discs) to sqrt(3.5) (spheres) times
            // more damped than the normal one (e = 0.1: zeta_n 0.59, zeta_t 1.02; its discs
            // kept spinning at the spring-only step and never settled).
            auto other_modes = [&](Real tc_normal, Real kt_over_kn, DampingRatios zeta,
                                   const std::string& what) {
                const Real tangential_ratio = std::sqrt(kt_over_kn * c_t * meff);
                if (zeta.normal > 0)
                    consider(safety * tc_normal / (2 * zeta.normal),
                             fmt::format("{} x normal dashpot, {} ({})", safety, what, pair));
                if (tangential_ratio > 0)
                    consider(safety * tc_normal / tangential_ratio,
                             fmt::format("{} x tangential-rotational {} ({})", safety, what, pair));
                // the tangential dashpot's ratio on the contact point's mass 1 / c_t
                const Real zeta_t = zeta.tangential * std::sqrt(c_t * meff);
                if (tangential_ratio > 0 && zeta_t > 0)
                    consider(safety * tc_normal / (2 * zeta_t * tangential_ratio),
                             fmt::format("{} x tangential-rotational dashpot, {} ({})", safety,
                                         what, pair));
                if (rolling_ratio > 0)
                    consider(safety * tc_normal / rolling_ratio,
                             fmt::format("{} x rolling {} ({})", safety, what, pair));
            };
            ContactLawRegistry::visit_index(p.law, [&]<class L>() {
                const Real tc = L::contact_time(p, meff, reff, vref);
                const std::string what =
                    L::speed_dependent_time
                        ? fmt::format("{} contact time at {:.3g} m/s", L::name, vref)
                        : fmt::format("{} contact time", L::name);
                consider(safety * tc, fmt::format("{} x {} ({})", safety, what, pair));
                other_modes(L::undamped_contact_time(p, meff, reff, vref), L::tangential_ratio(p),
                            L::damping_ratios(p), what);
                // Rayleigh time pi r sqrt(rho/G) / (0.1631 nu + 0.8766) of the grain material.
                if (L::stiffness == Stiffness::moduli && !ma.rigid && ma.youngs_modulus > 0) {
                    const Real g = ma.youngs_modulus / (2 * (1 + ma.poisson));
                    const Real tr =
                        pi * r1 * std::sqrt(ma.density / g) / (0.1631 * ma.poisson + 0.8766);
                    consider(0.2 * tr, fmt::format("0.2 x Rayleigh time ({})", ma.name));
                }
            });
        }
    }
    return best;
}

} // namespace debrisflow::dem
