#pragma once
#include "debrisflow/dem/contact_laws_k.hpp"
#include "debrisflow/dem/contact_params.hpp"
#include "debrisflow/dem/tsuji_damping.hpp"
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace debrisflow::dem {

// A law with material keys of its own (LawType::MaterialKeys, read_keys, read_override).
template <class L>
concept HasMaterialKeys = requires {
    typename L::MaterialKeys;
};

// One law's keys on a material (empty for a law without keys of its own) and on a [[contact]].
template <class L> struct LawKeysSlot {};
template <HasMaterialKeys L> struct LawKeysSlot<L> { typename L::MaterialKeys keys; };
template <class L> struct LawOverrideSlot {};
template <HasMaterialKeys L> struct LawOverrideSlot<L> {
    std::optional<typename L::MaterialKeys> keys;
};
template <class R> struct LawKeyTables;
template <class... L> struct LawKeyTables<models::Registry<L...>> {
    using Keys = std::tuple<LawKeysSlot<L>...>;
    using Overrides = std::tuple<LawOverrideSlot<L>...>;
};

// A named grain or wall material as the case file gives it.
struct Material {
    std::string name;
    std::string law =
        "linear";     // contact law for contacts of this material (see ContactLawRegistry)
    Real density = 0; // [kg/m^3] (grains)
    Real youngs_modulus = 0, poisson = 0.25; // [Pa], [-] (laws with Stiffness::moduli)
    bool rigid = false;                      // infinitely stiff (E* from the other side only)
    Real kn = 0, kt = 0;                     // linear springs [N/m]
    Real restitution = 0.5, friction = 0.5, rolling_friction = 0;
    // every law's own keys (read whatever the material's law, for pairs of another law)
    LawKeyTables<ContactLawRegistry>::Keys law_keys;
    template <class L> auto& keys() { return std::get<LawKeysSlot<L>>(law_keys).keys; }
    template <class L> const auto& keys() const { return std::get<LawKeysSlot<L>>(law_keys).keys; }
};

// Per-pair values that override the defaults derived from the two materials.
struct PairOverride {
    std::string a, b;
    std::optional<std::string> law;
    std::optional<Real> kn, kt, restitution, friction, rolling_friction;
    LawKeyTables<ContactLawRegistry>::Overrides law_keys;
    template <class L> auto& keys() { return std::get<LawOverrideSlot<L>>(law_keys).keys; }
    template <class L> const auto& keys() const {
        return std::get<LawOverrideSlot<L>>(law_keys).keys;
    }
};

// Hertz compliance (1 - nu^2) / E of one side of a contact (0 for a rigid material):
// 1/E* = the sum over both sides (Johnson 1985, eq. 4.22).
Real hertz_compliance(const Material& m);

// Pair table over all materials: law and parameters of every (i, j) pair. Defaults: the law
// of the grain side (the first of the pair when both are grains: both must agree), linear
// springs as series springs 2 k_i k_j/(k_i + k_j), other coefficients the mean of the two;
// a rigid material contributes nothing to E* and G*; the law's own keys as the law combines
// them (LawType::configure).
std::vector<PairParams> build_pair_table(const std::vector<Material>& mats,
                                         const std::vector<PairOverride>& overrides,
                                         const std::string& rolling);

// The farthest any pair of the table acts beyond touch (an adhesive law's reach) for
// effective radii up to r_max; 0 when no law is adhesive.
Real largest_reach(const std::vector<PairParams>& table, Real r_max);

} // namespace debrisflow::dem
