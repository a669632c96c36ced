#include "debrisflow/dem/materials.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/contact_laws_k.hpp"
#include "debrisflow/dem/rolling_models_k.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace debrisflow::dem {

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
    const auto roll = RollingRegistry::visit_name(
        rolling, []<class M>() { return std::uint8_t(RollingRegistry::index_of<M>()); });
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
            ContactLawRegistry::visit_name(law, [&]<class L>() {
                p.law = std::uint8_t(ContactLawRegistry::index_of<L>());
                if constexpr (HasMaterialKeys<L>)
                    L::configure(p, a.keys<L>(), b.keys<L>(),
                                 o ? o->keys<L>() : std::optional<typename L::MaterialKeys>{});
                else
                    L::configure(p);
            });
            table[i * n + j] = p;
        }
    return table;
}

Real largest_reach(const std::vector<PairParams>& table, Real r_max) {
    Real reach = 0;
    for (const PairParams& p : table) reach = std::max(reach, Laws::reach(p, r_max));
    return reach;
}

} // namespace debrisflow::dem
