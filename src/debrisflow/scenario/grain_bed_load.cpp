#include "debrisflow/scenario/grain_bed_load.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/contact_laws_k.hpp"
#include "debrisflow/dem/law_overlap.hpp"
#include "debrisflow/dem/materials.hpp"
#include "debrisflow/scenario/build_grains.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::scenario {

namespace {

// Span of the points' projections on axis e.
Real span_along(const dem::GrainSet& g, Index first, Index last, Vec3 e) {
    Real lo = std::numeric_limits<Real>::max(), hi = -lo;
    for (Index i = first; i < last; ++i) {
        const Real s = dot(g.pos[std::size_t(i)], e);
        lo = std::min(lo, s), hi = std::max(hi, s);
    }
    return hi - lo;
}

std::string stiffness_key(const io::CaseSpec& c, int material, const std::string& key) {
    const auto m = std::size_t(material);
    return m < c.dem.material_origins.size()
               ? c.dem.material_origins[m].at(key)
               : c.file + ": material '" + c.dem.materials[m].name + "' key '" + key + "'";
}

bool uses_springs(const dem::PairParams& p) {
    return dem::ContactLawRegistry::visit_index(
        p.law, []<class L>() { return L::stiffness == dem::Stiffness::springs; });
}

// "key = value to about value x factor" for the material whose stiffness sets pair p's: k_n
// for springs, Young's modulus for the elastic laws (a law's force and work grow in proportion).
std::string stiffness_to_raise(const io::CaseSpec& c, const dem::PairParams& p, int material,
                               Real factor) {
    const bool springs = uses_springs(p);
    const auto& m = c.dem.materials[std::size_t(material)];
    const Real value = springs ? m.kn : m.youngs_modulus;
    return fmt::format("{} = {:.4g} to about {:.3g}",
                       stiffness_key(c, material, springs ? "kn" : "youngs_modulus"), value,
                       value * factor);
}

// Mass and mean radius of grains [first, last) (a clump's members carry shares of its mass).
std::pair<Real, Real> mass_and_mean_radius(const dem::GrainSet& g, Index first, Index last) {
    Real mass = 0, radius_sum = 0;
    for (Index i = first; i < last; ++i) {
        mass += g.mass[std::size_t(i)];
        radius_sum += g.radius[std::size_t(i)];
    }
    return {mass, radius_sum / Real(last - first)};
}

// Which of the nm materials grains [first, last) are made of.
std::vector<bool> materials_of(const dem::GrainSet& g, Index first, Index last, int nm) {
    std::vector<bool> present(std::size_t(nm), false);
    for (Index i = first; i < last; ++i) present[g.material[std::size_t(i)]] = true;
    return present;
}

// The materials of a case's walls (-1: walls without one take the grain's own).
std::vector<int> wall_materials(const io::CaseSpec& c) {
    std::vector<int> walls;
    for (const auto& w : c.walls) {
        const int m = w.material.empty() ? -1 : material_index(c, w.material);
        if (std::find(walls.begin(), walls.end(), m) == walls.end()) walls.push_back(m);
    }
    return walls;
}

// Of a pair's two materials, the one whose stiffness to raise: the softer.
int softer_of(const dem::PairParams& p, const std::vector<dem::Material>& m, int a, int b) {
    const auto &ma = m[std::size_t(a)], &mb = m[std::size_t(b)];
    if (uses_springs(p)) return mb.kn > 0 && mb.kn < ma.kn ? b : a;
    return !mb.rigid && (ma.rigid || mb.youngs_modulus < ma.youngs_modulus) ? b : a;
}

} // namespace

BedOverlap require_bed_rests_on_contacts(const io::CaseSpec& c, const io::GrainsSpec& block,
                                         const dem::GrainSet& g, Index first, Index last) {
    BedOverlap out;
    const Vec3 gravity = c.dem.params.gravity;
    const Real gmag = norm(gravity);
    if (last <= first || !(gmag > 0)) return out;
    const Vec3 down = (1 / gmag) * gravity;
    const auto [mass, r] = mass_and_mean_radius(g, first, last);
    const Real d = 2 * r;
    // The footprint: the block's extent across gravity, one diameter added for the grains'
    // own size.
    Real footprint = 0, grain_area = 0;
    if (c.dim == 2) {
        const Vec3 across = cross(down, Vec3{0, 1, 0});
        footprint = (span_along(g, first, last, (1 / norm(across)) * across) + d) * c.dem.thickness;
        grain_area = d * c.dem.thickness;
    } else {
        const Vec3 trial = std::abs(down.x) < Real(0.9) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        Vec3 e1 = cross(down, trial);
        e1 = (1 / norm(e1)) * e1;
        const Vec3 e2 = cross(down, e1);
        footprint = (span_along(g, first, last, e1) + d) * (span_along(g, first, last, e2) + d);
        grain_area = d * d;
    }
    const Real force = mass * gmag / footprint * grain_area;

    const auto& materials = c.dem.materials;
    const int nm = int(materials.size());
    const auto table = dem::build_pair_table(materials, c.dem.overrides, c.dem.params.rolling);
    // The partners of the block's grains: one another, and each wall material (-1: walls
    // without one take the grain's own).
    const std::vector<int> walls = wall_materials(c);
    const std::vector<bool> present = materials_of(g, first, last, nm);
    const dem::PairParams* limiting = nullptr;
    Real limiting_r_eff = 0;
    int softer = 0; // the material whose stiffness sets the limiting pair's
    for (int a = 0; a < nm; ++a) {
        if (!present[std::size_t(a)]) continue;
        struct Partner {
            int material;
            bool wall;
            std::string name;
        };
        std::vector<Partner> partners{{a, false, materials[std::size_t(a)].name}};
        for (int w : walls)
            partners.push_back(w < 0 ? Partner{a, true, "wall"}
                                     : Partner{w, true, materials[std::size_t(w)].name + " wall"});
        for (const auto& [b, wall, name] : partners) {
            const dem::PairParams& p = table[std::size_t(a * nm + b)];
            const Real r_eff = wall ? r : r / 2;
            const Real overlap = dem::overlap_carrying(p, r_eff, force, 2 * r);
            if (overlap / r <= out.fraction) continue;
            out = {overlap / r, overlap, force,
                   fmt::format("grains '{}', {}-{} contact", block.name,
                               materials[std::size_t(a)].name, name)};
            limiting = &p, limiting_r_eff = r_eff;
            softer = softer_of(p, materials, a, b);
        }
    }
    if (!(out.fraction > max_bed_overlap)) return out;

    // The contact force is proportional to k_n (linear) or E* (Hertz, DCDEM): scaling the
    // stiffness by force / F(1 % of r) brings the overlap to about 1 %.
    const Real factor = force / dem::elastic_force(*limiting, limiting_r_eff, Real(0.01) * r);
    throw InputError(fmt::format(
        "{}: the grains are too soft to rest on their contacts: the bed's own weight ({:.4g} kg "
        "over {:.4g} m^2) presses each contact at its base with about {:.3g} N, which sinks the "
        "{} {}{:.3g} m deep, {:.0f} % of the grains' mean radius {:.3g} m (refused above {:.0f} %; "
        "a DEM contact should stay well under 1 %, or grains pass through one another and "
        "through walls); raise {} for 1 %",
        block.origin.block(), mass, footprint, force, out.where.substr(out.where.find(", ") + 2),
        out.overlap >= 2 * r ? "more than " : "", out.overlap, 100 * out.fraction, r,
        100 * max_bed_overlap, stiffness_to_raise(c, *limiting, softer, factor)));
}

namespace {

// The largest projection on `down` of the domain's corners: its lowest point along gravity.
Real domain_floor(const io::CaseSpec& c, Vec3 down) {
    Real floor = -std::numeric_limits<Real>::max();
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner{(k & 1) ? c.domain.hi.x : c.domain.lo.x,
                          c.dim == 2 ? 0 : ((k & 2) ? c.domain.hi.y : c.domain.lo.y),
                          (k & 4) ? c.domain.hi.z : c.domain.lo.z};
        floor = std::max(floor, dot(corner, down));
    }
    return floor;
}

// What is thrown at the walls: a grain of mass m and radius r of the given materials, released
// at `released` m/s from `top` (its highest point), given by `where` for the error.
struct Throw {
    std::string where, what; // "case.toml:3:1: key 'grains.0.velocity'", "grains 'column'"
    Real released = 0;       // [m/s]
    Vec3 top;                // the highest release point
    Real mass = 0, radius = 0;
    std::string size;            // "mean", "largest"
    std::vector<bool> materials; // which materials the grains are made of
};

// The fastest impact: no force but gravity can speed a grain up beyond the energy it gains
// falling from its release to the domain's lowest point, |v|^2 = |v0|^2 + 2 g h.
void require_throw_within_contact(const io::CaseSpec& c, const Throw& t) {
    const Real gmag = norm(c.dem.params.gravity);
    const Real fall = gmag > 0
                          ? std::max(Real(0), domain_floor(c, (1 / gmag) * c.dem.params.gravity) -
                                                  dot(t.top, (1 / gmag) * c.dem.params.gravity))
                          : Real(0);
    const Real speed = std::sqrt(t.released * t.released + 2 * gmag * fall);
    const auto& materials = c.dem.materials;
    const int nm = int(materials.size());
    const auto table = dem::build_pair_table(materials, c.dem.overrides, c.dem.params.rolling);
    for (int a = 0; a < nm; ++a) {
        if (!t.materials[std::size_t(a)]) continue;
        for (const auto& wall : c.walls) {
            // a moving wall meets the grain head-on at the sum of the speeds
            const Real closing = speed + norm(wall.velocity);
            if (!(closing > 0)) continue;
            const int b = wall.material.empty() ? a : material_index(c, wall.material);
            const dem::PairParams& p = table[std::size_t(a * nm + b)];
            const Real m = t.mass, r = t.radius, energy = Real(0.5) * m * closing * closing;
            const Real overlap = dem::overlap_absorbing(p, r, energy, 2 * r);
            if (!(overlap > max_impact_overlap * r)) continue;
            // The elastic work is proportional to k_n (linear) or E* (Hertz, DCDEM).
            const Real factor = energy / dem::elastic_work(p, r, max_bed_overlap * r);
            const std::string how =
                fall > 0 ? fmt::format("reaching {:.4g} m/s ({:.4g} m/s at release, then a fall of "
                                       "{:.4g} m to the domain's lowest point)",
                                       speed, t.released, fall)
                         : fmt::format("at {:.4g} m/s", speed);
            const std::string moving =
                norm(wall.velocity) > 0
                    ? fmt::format(" moving at {:.4g} m/s towards them ({})", norm(wall.velocity),
                                  wall.origin.at("velocity"))
                    : "";
            throw InputError(fmt::format(
                "{}: {} {} are too fast for their contacts: a grain of the {} size ({:.3g} kg, "
                "radius {:.3g} m) hitting the {} wall '{}'{} head-on sinks {}{:.3g} m into it "
                "before it stops, {:.0f} % of its radius (refused above {:.0f} %: it would pass "
                "through walls and other grains); raise {} for {:.0f} %, or lower the speed",
                t.where, t.what, how, t.size, t.mass, r, materials[std::size_t(b)].name, wall.name,
                moving, overlap >= 2 * r ? "more than " : "", overlap, 100 * overlap / r,
                100 * max_impact_overlap,
                stiffness_to_raise(c, p, softer_of(p, materials, a, b), factor),
                100 * max_bed_overlap));
        }
    }
}

// The point of grains [first, last) highest against gravity (any grain without gravity).
Vec3 highest_grain(const dem::GrainSet& g, Index first, Index last, Vec3 gravity) {
    Vec3 top = g.pos[std::size_t(first)];
    for (Index i = first; i < last; ++i)
        if (dot(g.pos[std::size_t(i)], gravity) < dot(top, gravity)) top = g.pos[std::size_t(i)];
    return top;
}

} // namespace

void require_impact_within_contact(const io::CaseSpec& c, const io::GrainsSpec& block,
                                   const dem::GrainSet& g, Index first, Index last) {
    if (last <= first) return;
    Real speed = 0;
    for (Index i = first; i < last; ++i) speed = std::max(speed, norm(g.vel[std::size_t(i)]));
    const auto [mass, r] = mass_and_mean_radius(g, first, last);
    require_throw_within_contact(c, {speed > 0 ? block.origin.at("velocity") : block.origin.block(),
                                     fmt::format("grains '{}'", block.name), speed,
                                     highest_grain(g, first, last, c.dem.params.gravity),
                                     mass / Real(last - first), r, "mean",
                                     materials_of(g, first, last, int(c.dem.materials.size()))});
}

void require_feed_within_contact(const io::CaseSpec& c, const io::FeedSpec& feed,
                                 const dem::GrainSet& largest) {
    const Vec3 gdir = c.dem.params.gravity;
    Vec3 top = feed.min; // the region's corner highest against gravity
    for (int a = 0; a < 3; ++a)
        if (gdir[a] > 0)
            top[a] = feed.min[a];
        else if (gdir[a] < 0)
            top[a] = feed.max[a];
    if (c.dim == 2) top.y = 0;
    Throw t{norm(feed.velocity) > 0 ? feed.origin.at("velocity") : feed.origin.block(),
            fmt::format("the grains of feed '{}'", feed.name),
            norm(feed.velocity),
            top,
            largest.mass[0],
            largest.radius[0],
            "largest",
            materials_of(largest, 0, 1, int(c.dem.materials.size()))};
    require_throw_within_contact(c, t);
}

} // namespace debrisflow::scenario
