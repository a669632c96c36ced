#include "debrisflow/io/dem_reader.hpp"
#include "debrisflow/coupling/drag_laws_k.hpp"
#include "debrisflow/dem/contact_laws_k.hpp"
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/dem/rolling_models_k.hpp"
#include "debrisflow/io/named.hpp"
#include "debrisflow/io/size_window.hpp"
#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::io {

namespace {

// A law's traits by name (the registry's), for the checks of materials and contacts.
struct LawTraits {
    dem::Stiffness stiffness;
    Real min_restitution;
    bool uses_restitution;
};
LawTraits law_traits(const std::string& law) {
    return dem::ContactLawRegistry::visit_name(law, []<class L>() {
        return LawTraits{L::stiffness, L::min_restitution, L::uses_restitution};
    });
}

void check_restitution(const ConfigTable& t, Real e, const std::string& law) {
    if (!(e > 0 && e <= 1)) t.fail("restitution", "must be within (0, 1]");
    const Real least = law_traits(law).min_restitution;
    if (e < least)
        t.fail("restitution", fmt::format("must be within [{}, 1] for the {} law (the Tsuji "
                                          "damping of a lower one is overdamped)",
                                          least, law));
}

dem::Material read_material(const ConfigTable& t) {
    dem::Material m;
    m.name = t.name("name");
    m.law = t.choice("law", dem::ContactLawRegistry::names(), "linear");
    const LawTraits law = law_traits(m.law);
    m.rigid = t.boolean("rigid", false);
    m.density = t.has("density") || !m.rigid ? t.positive("density", 2650) : 0;
    // The law's own stiffness keys are required; the others' are read when given (for pairs
    // of another law).
    if (law.stiffness == dem::Stiffness::springs || t.has("kn")) {
        m.kn = t.positive("kn");
        m.kt = t.positive("kt", m.kn);
    }
    if (law.stiffness == dem::Stiffness::moduli || t.has("youngs_modulus")) {
        if (!m.rigid) m.youngs_modulus = t.positive("youngs_modulus");
        m.poisson = t.real("poisson", 0.25);
        if (m.poisson < 0 || m.poisson >= 0.5) t.fail("poisson", "must be within [0, 0.5)");
    }
    if (!law.uses_restitution && t.has("restitution"))
        t.fail("restitution",
               fmt::format("not a parameter of the {} law, which has its own damping key; give a "
                           "pair with another material its restitution in a [[contact]]",
                           m.law));
    m.restitution = t.real("restitution", 0.5);
    check_restitution(t, m.restitution, m.law);
    m.friction = t.real("friction", 0.5);
    if (m.friction < 0) t.fail("friction", "must be >= 0");
    m.rolling_friction = t.real("rolling_friction", 0);
    if (m.rolling_friction < 0) t.fail("rolling_friction", "must be >= 0");
    dem::ContactLawRegistry::for_each([&]<class L>() {
        if constexpr (dem::HasMaterialKeys<L>) m.keys<L>() = L::read_keys(t, m.law == L::name);
    });
    t.finish();
    return m;
}

dem::PairOverride read_contact(const ConfigTable& t, const std::vector<dem::Material>& mats) {
    dem::PairOverride o;
    const auto names = t.strings("materials");
    if (names.size() != 2) t.fail("materials", "expected two material names");
    for (const auto& n : names) require_named(t, "materials", mats, n, "[[material]]");
    o.a = names[0];
    o.b = names[1];
    if (t.has("law")) o.law = t.choice("law", dem::ContactLawRegistry::names());
    if (t.has("kn")) o.kn = t.positive("kn");
    if (t.has("kt")) o.kt = t.positive("kt");
    if (t.has("restitution")) {
        o.restitution = t.real("restitution");
        check_restitution(t, *o.restitution, o.law ? *o.law : find_named(mats, o.a)->law);
    }
    for (const char* key : {"friction", "rolling_friction"})
        if (t.has(key) && t.real(key) < 0) t.fail(key, "must be >= 0 (as on a [[material]])");
    if (t.has("friction")) o.friction = t.real("friction");
    if (t.has("rolling_friction")) o.rolling_friction = t.real("rolling_friction");
    dem::ContactLawRegistry::for_each([&]<class L>() {
        if constexpr (dem::HasMaterialKeys<L>) o.keys<L>() = L::read_override(t);
    });
    t.finish();
    return o;
}

// Grain sizes of debris flows run from silt (1e-6 m) to boulders; a grain must fit in the
// domain's smallest extent.
void check_size_range(const ConfigTable& t, const SizeSpec& s, const CaseSpec& c) {
    const std::string key = t.has("diameter") ? "diameter" : "size";
    if (s.min < 1e-6)
        t.fail(key, fmt::format("the smallest grain ({:.3g} m) is below 1e-6 m", s.min));
    Real extent = std::numeric_limits<Real>::max();
    for (int d = 0; d < 3; ++d)
        if (!(c.dim == 2 && d == 1)) extent = std::min(extent, c.domain.hi[d] - c.domain.lo[d]);
    if (!(s.max < extent))
        t.fail(key, fmt::format("the largest grain ({:.4g} m) does not fit in the domain, whose "
                                "smallest extent is {:.4g} m",
                                s.max, extent));
}

SizeSpec read_size(const ConfigTable& t) {
    SizeSpec s;
    if (t.has("diameter")) {
        s.diameter = t.positive("diameter");
        s.min = s.max = s.diameter;
        return s;
    }
    auto size = t.table("size");
    if (!size) t.fail("diameter", "give a diameter or a [size] table");
    s.distribution = size->choice("distribution", {"mono", "lognormal", "sieve"});
    if (s.distribution == "mono") {
        s.diameter = size->positive("diameter");
        s.min = s.max = s.diameter;
    } else if (s.distribution == "lognormal") {
        s.d50 = size->positive("d50");
        s.sigma = size->positive("sigma");
        s.min = size->positive("min", s.d50 * std::exp(-3 * s.sigma));
        s.max = size->positive("max", s.d50 * std::exp(3 * s.sigma));
    } else {
        s.sieve_sizes = size->reals("sizes");
        s.sieve_passing = size->reals("passing");
        if (s.sieve_sizes.size() < 2 || s.sieve_sizes.size() != s.sieve_passing.size())
            size->fail("passing", "needs as many entries as sizes (at least two)");
        for (std::size_t i = 1; i < s.sieve_sizes.size(); ++i) {
            if (!(s.sieve_sizes[i] > s.sieve_sizes[i - 1]))
                size->fail("sizes", "must increase strictly");
            if (s.sieve_passing[i] < s.sieve_passing[i - 1])
                size->fail("passing", "must not decrease");
        }
        if (s.sieve_sizes[0] <= 0) size->fail("sizes", "must be > 0");
        if (s.sieve_passing.front() < 0 || s.sieve_passing.back() > 100)
            size->fail("passing", "percentages must be within [0, 100]");
        s.min = size->positive("min", s.sieve_sizes.front());
        s.max = size->positive("max", s.sieve_sizes.back());
    }
    if (s.max < s.min) size->fail("max", "must be >= min");
    // A window that holds (almost) none of the distribution is a mistake, not a case: say so
    // instead of drawing from a vanishing tail.
    if (s.distribution == "lognormal") {
        const Real kept = lognormal_window_probability(s);
        if (!(kept >= 1e-9))
            size->fail(size->has("max") ? "max" : "min",
                       fmt::format("the window [min, max] = [{:.4g}, {:.4g}] m holds {:.3g} of the "
                                   "lognormal distribution (d50 = {:.4g} m, sigma = {:.4g}); "
                                   "check d50, sigma, min and max",
                                   s.min, s.max, kept, s.d50, s.sigma));
    } else if (s.distribution == "sieve") {
        if (!(s.sieve_passing.back() > s.sieve_passing.front()))
            size->fail("passing", "must rise from the first sieve to the last");
        const Real kept = sieve_window_mass_fraction(s);
        if (!(kept >= 1e-9))
            size->fail(size->has("max") ? "max" : "min",
                       fmt::format("the window [min, max] = [{:.4g}, {:.4g}] m holds {:.3g} of "
                                   "the sieve curve's mass (sizes {:.4g} to {:.4g} m)",
                                   s.min, s.max, kept, s.sieve_sizes.front(),
                                   s.sieve_sizes.back()));
    }
    size->finish();
    return s;
}

GrainsSpec read_grains(const ConfigTable& t, const CaseSpec& c) {
    GrainsSpec g;
    g.origin = t.origin();
    g.name = t.name("name");
    g.packing = t.choice("packing", {"random", "lattice", "single", "file"}, "random");
    const bool file = g.packing == "file";
    // A saved state keeps each grain's own material, velocity and spin unless the block gives
    // them; a region keeps the grains whose centre lies in it.
    g.file_overrides = {t.has("material"), t.has("velocity"), t.has("angular_velocity"),
                        t.has("region")};
    g.material = file ? t.string("material", "") : t.string("material");
    if (!file || !g.material.empty())
        require_named(t, "material", c.dem.materials, g.material, "[[material]]");
    g.velocity = t.vec3("velocity", c.dim, {});
    g.angular_velocity = t.vec3("angular_velocity", 3, {});
    if (t.has("clump")) {
        if (file)
            t.fail("clump", "a saved grain state holds spheres only; clumps are built from "
                            "packing = \"random\", \"lattice\" or \"single\"");
        // rows (x, y, z, r), as a [[body]] clump's spheres; y is ignored in 2D
        for (const auto& r : t.rows("clump", 4)) {
            if (!(r[3] > 0)) t.fail("clump", "radii (4th number of each row) must be > 0");
            g.clump_centers.push_back({r[0], c.dim == 2 ? 0 : r[1], r[2]});
            g.clump_radii.push_back(r[3]);
        }
        if (g.clump_centers.size() < 2)
            t.fail("clump", "a clump needs at least two spheres (one is a plain grain)");
        if (g.clump_centers.size() > 64) t.fail("clump", "at most 64 spheres per clump");
        g.clump_aligned = t.choice("orientation", {"random", "aligned"}, "random") == "aligned";
    }
    if (file) {
        g.file = t.string("file");
        if (auto region = t.table("region")) {
            g.region = read_shape(*region, c.dim, {"box", "cylinder", "stl"});
            region->finish();
        }
        t.finish();
        return g;
    }
    g.size = read_size(t);
    check_size_range(t, g.size, c);
    if (g.packing == "single") {
        g.position = t.vec3("position", c.dim);
    } else {
        auto region = t.table("region");
        if (!region) t.fail("region", "missing [grains.region] table (shape = \"box\" ...)");
        g.region = read_shape(*region, c.dim, {"box", "cylinder", "stl"});
        region->finish();
        if (g.packing == "random") {
            if (t.has("count") == t.has("mass")) t.fail("count", "give either count or mass");
            if (t.has("count")) {
                g.count = t.integer("count", 0, 1, 2000000000);
            } else {
                g.mass = t.positive("mass");
            }
            g.seed = unsigned(t.integer("seed", 1, 0, 4294967295L));
        } else {
            g.gap = t.real("gap", 0.001);
            if (g.gap < 0) t.fail("gap", "must be >= 0");
            if (g.size.min != g.size.max) t.fail("packing", "a lattice needs one diameter");
        }
    }
    t.finish();
    return g;
}

FeedSpec read_feed(const ConfigTable& t, const CaseSpec& c) {
    FeedSpec f;
    f.origin = t.origin();
    f.name = t.name("name");
    f.material = t.string("material");
    require_named(t, "material", c.dem.materials, f.material, "[[material]]");
    f.size = read_size(t);
    check_size_range(t, f.size, c);
    f.min = t.vec3("min", c.dim);
    f.max = t.vec3("max", c.dim);
    for (int k = 0; k < 3; ++k)
        if (!(c.dim == 2 && k == 1) && !(f.max[k] - f.min[k] > f.size.max))
            t.fail("max",
                   fmt::format("the region must exceed the largest diameter in {}", "xyz"[k]));
    if (t.has("times")) {
        f.times = t.reals("times");
        f.discharge = t.reals("discharge");
        if (f.times.size() != f.discharge.size() || f.times.empty())
            t.fail("discharge", "needs one value per entry of 'times' (a hydrograph)");
        for (std::size_t k = 1; k < f.times.size(); ++k)
            if (!(f.times[k] > f.times[k - 1])) t.fail("times", "must increase");
    } else {
        f.discharge = {t.real("discharge")};
        f.times = {0};
    }
    for (Real q : f.discharge)
        if (q < 0) t.fail("discharge", "must be >= 0 [m^3/s of solid] (2D: m^2/s)");
    f.velocity = t.vec3("velocity", c.dim, {});
    f.seed = unsigned(t.integer("seed", 1, 0, 4294967295L));
    f.every = t.positive("every", 0.01);
    if (t.has("rocks")) {
        if (c.dim == 2) t.fail("rocks", "rock feeds (STL shapes) need dimensions = 3");
        for (const auto& name : t.strings("rocks")) {
            std::filesystem::path p(name);
            if (p.is_relative()) p = std::filesystem::path(t.file()).parent_path() / p;
            if (!std::filesystem::exists(p)) t.fail("rocks", "mesh file not found: " + p.string());
            f.rocks.push_back(p.string());
        }
        if (f.rocks.empty()) t.fail("rocks", "list at least one STL shape");
        f.sphericity_tolerance = t.real("sphericity_tolerance", Real(0.15));
        if (!(f.sphericity_tolerance >= 0 && f.sphericity_tolerance < 1))
            t.fail("sphericity_tolerance", "must be in [0, 1) (0.15: +-15 %)");
        f.layers = int(t.integer("layers", 0, 0, max_boundary_layers));
    }
    t.finish();
    return f;
}

// Two materials with different contact laws meet under the law of a [[contact]] that names
// them (none would be the right default); a dcdem material has no restitution, so such a
// contact of another law must give one.
void check_mixed_laws(const std::vector<dem::Material>& mats,
                      const std::vector<dem::PairOverride>& overrides,
                      const std::vector<ConfigTable>& material_tables,
                      const std::vector<ConfigTable>& contact_tables) {
    for (std::size_t j = 0; j < mats.size(); ++j)
        for (std::size_t i = 0; i < j; ++i) {
            const dem::Material &a = mats[i], &b = mats[j];
            const dem::PairOverride* o = nullptr;
            std::size_t k = 0;
            for (std::size_t n = 0; n < overrides.size(); ++n)
                if ((overrides[n].a == a.name && overrides[n].b == b.name) ||
                    (overrides[n].a == b.name && overrides[n].b == a.name))
                    o = &overrides[n], k = n;
            if (a.law != b.law && !(o && o->law))
                material_tables[j].fail(
                    "law", fmt::format("material \"{}\" ({}) and \"{}\" ({}) have different "
                                       "contact laws: add a [[contact]] with materials = "
                                       "[\"{}\", \"{}\"] and the law of their pair",
                                       b.name, b.law, a.name, a.law, a.name, b.name));
            const std::string law = o && o->law ? *o->law : a.law;
            const bool a_has = law_traits(a.law).uses_restitution,
                       b_has = law_traits(b.law).uses_restitution;
            if (law_traits(law).uses_restitution && !(a_has && b_has) && !o->restitution)
                contact_tables[k].fail(
                    "restitution",
                    fmt::format("required: the pair \"{}\"-\"{}\" uses {}, and the {} material "
                                "has no restitution",
                                a.name, b.name, law, a_has ? b.law : a.law));
        }
}

} // namespace

void read_dem(const ConfigTable& root, CaseSpec& c) {
    const auto material_tables = root.tables("material");
    for (const auto& t : material_tables) {
        c.dem.materials.push_back(read_material(t));
        c.dem.material_origins.push_back(t.origin());
        for (std::size_t i = 0; i + 1 < c.dem.materials.size(); ++i)
            if (c.dem.materials[i].name == c.dem.materials.back().name)
                t.fail("name", "two materials are named \"" + c.dem.materials[i].name + "\"");
    }
    if (c.dem.materials.size() > 250) root.fail("material", "at most 250 materials");
    const auto contact_tables = root.tables("contact");
    for (const auto& t : contact_tables)
        c.dem.overrides.push_back(read_contact(t, c.dem.materials));
    check_mixed_laws(c.dem.materials, c.dem.overrides, material_tables, contact_tables);
    for (const auto& t : root.tables("grains")) {
        c.dem.grains.push_back(read_grains(t, c));
        if (c.dem.materials.empty()) t.fail("material", "define a [[material]] first");
    }
    for (const auto& t : root.tables("feed")) {
        if (c.dem.materials.empty()) t.fail("material", "define a [[material]] first");
        auto f = read_feed(t, c);
        (f.rocks.empty() ? c.dem.feeds : c.rigid.feeds).push_back(std::move(f));
    }
    c.has_dem = !c.dem.grains.empty() || !c.dem.feeds.empty();
    auto& p = c.dem.params;
    p.dim = c.dim;
    auto t = root.table("dem");
    if (!t) {
        if (c.has_dem && c.dim == 2)
            root.fail("dem", "a 2D case with grains needs [dem] thickness (disc thickness, m)");
        return;
    }
    if (!c.has_dem) t->fail("dt", "[dem] given but no [[grains]] or [[feed]]");
    c.dem_origin = t->origin();
    if (t->has("dt")) p.dt = t->positive("dt");
    p.safety = t->positive("safety", 0.02);
    if (p.safety > 0.3) t->fail("safety", "must be <= 0.3 (fraction of the contact time)");
    p.skin = t->positive("skin", 0.1);
    p.reference_velocity = t->real("reference_velocity", 0);
    p.rolling = t->choice("rolling", dem::RollingRegistry::names(), "none");
    p.subcycle = t->boolean("subcycle", !c.fluids.empty());
    p.reorder = t->boolean("reorder", true);
    p.slot_contacts = t->choice("contact_pass", {"ranges", "slots"}, "ranges") == "slots";
    c.dem.settle = t->boolean("settle", false);
    c.dem.settle_ratio = t->positive("settle_ratio", 0.01);
    c.dem.settle_max_time = t->positive("settle_max_time", 2);
    if (c.dim == 2) c.dem.thickness = t->positive("thickness");
    std::vector<std::string> drags{"none"};
    for (const auto& name : coupling::DragRegistry::names()) drags.push_back(name);
    c.dem.fluid_drag = t->choice("fluid_drag", drags, "none");
    if (c.dem.fluid_drag != "none" && c.fluids.empty())
        t->fail("fluid_drag", "couples grains to a fluid, but the case has no [[fluid]]");
    if (c.dem.fluid_drag != "none" && c.dim != 3)
        t->fail("fluid_drag", "the SPH-DEM drag coupling is 3D only (sphere drag laws)");
    t->finish();
}

} // namespace debrisflow::io
