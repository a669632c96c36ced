#pragma once
#include "debrisflow/core/hd.hpp"
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/laws/dcdem_law_k.hpp"
#include "debrisflow/dem/laws/hertz_mindlin_jkr_law_k.hpp"
#include "debrisflow/dem/laws/hertz_mindlin_law_k.hpp"
#include "debrisflow/dem/laws/law_types_k.hpp"
#include "debrisflow/dem/laws/linear_law_k.hpp"
#include "debrisflow/models/registry.hpp"

namespace debrisflow::dem {

// The contact laws, selectable by name (`law` of a [[material]] or [[contact]]). A law is a
// type in dem/laws/ with its name, normal response, reach, configuration from its materials'
// keys and its contact time; adding one is its file and a line here. A pair's PairParams::law
// is the law's position in this list.
using ContactLawRegistry =
    models::Registry<LinearLaw, HertzMindlinLaw, DcdemLaw, HertzMindlinJkrLaw>;

// Dispatch on a pair's law index, the same code on the host and a GPU.
template <class Registry> struct ContactLaws;
template <class... Laws> struct ContactLaws<models::Registry<Laws...>> {
    // Normal response and the law's factor on the Coulomb bound (vt2 = |v_t|^2).
    DF_HD DF_HOT_INLINE static NormalResponse normal(const PairParams& p, const ContactInput& c,
                                                     Real vt2, Real& friction_factor) {
        NormalResponse r{};
        std::uint8_t k = 0;
        (void)((p.law == k++
                    ? (r = Laws::normal(p, c), friction_factor = Laws::friction_factor(vt2), true)
                    : false) ||
               ...);
        return r;
    }
    // How far apart (a negative overlap) the pair still interacts: 0 for laws that act only
    // while the bodies overlap.
    DF_HD static Real reach(const PairParams& p, Real r_eff) {
        Real out = 0;
        std::uint8_t k = 0;
        (void)((p.law == k++ ? (out = Laws::reach(p, r_eff), true) : false) || ...);
        return out;
    }
};
using Laws = ContactLaws<ContactLawRegistry>;

DF_HD DF_HOT_INLINE NormalResponse normal_response(const PairParams& p, const ContactInput& c,
                                                   Real vt2, Real& friction_factor) {
    return Laws::normal(p, c, vt2, friction_factor);
}

// Whether a pair that does not overlap, its surfaces `gap` > 0 apart, is still within its
// law's reach. Callers test PairTable::adhesive first, so that a table without adhesive laws
// pays nothing for it.
DF_HD inline bool within_reach(const PairParams& p, Real gap, Real r_eff) {
    return gap < Laws::reach(p, r_eff);
}

} // namespace debrisflow::dem
