#include "debrisflow/scenario/build_grains.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/box_faces.hpp"
#include "debrisflow/dem/wall_proximity.hpp"
#include "debrisflow/io/named.hpp"
#include "debrisflow/scenario/clump_template.hpp"
#include "debrisflow/scenario/overlap_grid.hpp"
#include "debrisflow/scenario/resource_estimate.hpp"
#include "debrisflow/scenario/size_sampler.hpp"
#include "debrisflow/scenario/stl_mesh.hpp"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>

namespace debrisflow::scenario {

namespace {

constexpr Real pi = 3.14159265358979323846;

} // namespace

int material_index(const io::CaseSpec& c, const std::string& name) {
    const int i = io::index_named(c.dem.materials, name);
    if (i >= 0) return i;
    throw InputError(c.file + ": no material named \"" + name + "\"");
}

void add_grain(const io::CaseSpec& c, dem::GrainSet& g, Vec3 x, Vec3 v, Vec3 w, Real d, int mat) {
    const Real r = d / 2, rho = c.dem.materials[std::size_t(mat)].density;
    if (c.dim == 2) {
        x.y = 0, v.y = 0, w = {0, w.y, 0};
        const Real m = rho * pi * r * r * c.dem.thickness;
        g.set_spin(g.add(x, v, r, m, Real(0.5) * m * r * r, std::uint8_t(mat)), w);
    } else {
        const Real m = rho * Real(4) / 3 * pi * r * r * r;
        g.set_spin(g.add(x, v, r, m, Real(0.4) * m * r * r, std::uint8_t(mat)), w);
    }
}

namespace {

struct Region {
    const io::ShapeSpec& s;
    int dim;
    std::unique_ptr<TriangleMesh> mesh;
    Region(const io::ShapeSpec& shape, int d) : s(shape), dim(d) {
        if (s.type == "stl")
            mesh =
                std::make_unique<TriangleMesh>(TriangleMesh::read_stl(s.file, s.scale, s.offset));
    }
    void bounds(Vec3& lo, Vec3& hi) const {
        if (s.type == "box") {
            lo = s.min, hi = s.max;
        } else if (s.type == "cylinder") {
            const Real r = s.radius;
            lo = s.center - Vec3{r, r, r}, hi = s.center + Vec3{r, r, r};
            const Vec3 top = s.center + s.length * s.axis;
            for (int d = 0; d < 3; ++d)
                lo[d] = std::min(lo[d], top[d] - r), hi[d] = std::max(hi[d], top[d] + r);
        } else {
            mesh->bounds(lo, hi);
        }
        if (dim == 2) lo.y = hi.y = 0;
    }
    // Whether a grain of radius r centred at p lies inside (centre test for meshes).
    bool holds(Vec3 p, Real r) const {
        if (s.type == "box") {
            for (int d = 0; d < 3; ++d) {
                if (dim == 2 && d == 1) continue;
                if (p[d] - r < s.min[d] || p[d] + r > s.max[d]) return false;
            }
            return true;
        }
        if (s.type == "cylinder") {
            const Vec3 q = p - s.center;
            if (dim == 2) return dot(q, q) <= (s.radius - r) * (s.radius - r);
            const Real a = dot(q, s.axis);
            const Vec3 radial = q - a * s.axis;
            return a >= r && a <= s.length - r && norm(radial) <= s.radius - r;
        }
        return mesh->contains(p);
    }
};

// Makes the grains of a block: spheres (discs), or clumps of its template in a random (seeded)
// or the template's own orientation; `reach` is what a grain of size d needs around its
// centre (its radius, or its clump's bounding radius).
struct GrainMaker {
    const io::CaseSpec& c;
    const io::GrainsSpec& b;
    int mat;
    std::optional<ClumpTemplate> shape;
    std::mt19937_64 turn;
    GrainMaker(const io::CaseSpec& cs, const io::GrainsSpec& bs, int m)
        : c(cs), b(bs), mat(m), turn(0x9E3779B97F4A7C15ULL ^ bs.seed) {
        if (!b.clump_radii.empty()) shape = ClumpTemplate::from(b, c);
    }
    Real reach(Real d) const { return shape ? shape->bounding_radius(d) : d / 2; }
    // Adds one grain (or clump) of size d at p; returns the mass added.
    Real add(dem::GrainSet& g, Vec3 p, Real d) {
        const Index before = g.size();
        if (shape)
            add_clump(c, g, *shape, p, b.velocity, b.angular_velocity, d, mat,
                      b.clump_aligned ? rigid::Quat{} : random_orientation(turn, c.dim));
        else
            add_grain(c, g, p, b.velocity, b.angular_velocity, d, mat);
        Real m = 0;
        for (Index i = before; i < g.size(); ++i) m += g.mass[std::size_t(i)];
        return m;
    }
};

// Random sequential insertion: uniform trial positions, rejected on overlap with any grain
// already placed (clumps by their bounding spheres), found through a grid per size class.
void insert_random(const io::CaseSpec& c, const io::GrainsSpec& b, int mat, dem::GrainSet& g) {
    SizeSampler sizes(b.size, c.dim, b.seed);
    GrainMaker maker(c, b, mat);
    Region region(b.region, c.dim);
    Vec3 lo, hi;
    region.bounds(lo, hi);
    // Grains of earlier blocks are obstacles: the block fills the room they leave.
    Real r_lo = maker.reach(b.size.min), r_hi = maker.reach(b.size.max);
    for (Real r : g.radius) r_lo = std::min(r_lo, r), r_hi = std::max(r_hi, r);
    OverlapGrid placed(r_lo, r_hi, c.dim);
    for (std::size_t i = 0; i < g.radius.size(); ++i) placed.add(g.pos[i], g.radius[i]);
    std::uniform_real_distribution<Real> u(0, 1);
    auto& rng = sizes.rng();
    Real mass = 0;
    long count = 0, failures = 0;
    const long max_failures = 20000;
    Real d = sizes();
    while ((b.count > 0 && count < b.count) || (b.mass > 0 && mass < b.mass)) {
        const Real r = maker.reach(d);
        Vec3 p{lo.x + u(rng) * (hi.x - lo.x), c.dim == 2 ? 0 : lo.y + u(rng) * (hi.y - lo.y),
               lo.z + u(rng) * (hi.z - lo.z)};
        const bool ok = region.holds(p, r) && !placed.overlaps(p, r);
        if (!ok) {
            if (++failures > max_failures)
                throw InputError(fmt::format(
                    "{}: grains '{}': random insertion placed {} grains ({:.4g} kg) and found no "
                    "room for the next (diameter {:.4g} m) in {} tries; enlarge the region, use "
                    "packing = \"lattice\" and settle, or, for a wide gradation, give the coarse "
                    "fraction its own [[grains]] block before this one (later blocks fill around "
                    "earlier ones)",
                    b.origin.block(), b.name, count, mass, d, max_failures));
            continue;
        }
        failures = 0;
        placed.add(p, r);
        mass += maker.add(g, p, d);
        ++count;
        d = sizes();
    }
}

void fill_lattice(const io::CaseSpec& c, const io::GrainsSpec& b, int mat, dem::GrainSet& g) {
    Region region(b.region, c.dim);
    GrainMaker maker(c, b, mat);
    Vec3 lo, hi;
    region.bounds(lo, hi);
    const Real d = b.size.diameter > 0 ? b.size.diameter : b.size.min;
    const Real r = maker.reach(d), s = 2 * r * (1 + b.gap);
    require_lattice_within_budget(lo, hi, s, c.dim, b.origin.block() + ": grains '" + b.name + "'");
    long placed = 0;
    for (Real z = lo.z + r; z <= hi.z - r + 1e-12; z += s)
        for (Real y = c.dim == 2 ? 0 : lo.y + r; y <= (c.dim == 2 ? 0 : hi.y - r + 1e-12);
             y += (c.dim == 2 ? 1 : s))
            for (Real x = lo.x + r; x <= hi.x - r + 1e-12; x += s) {
                const Vec3 p{x, y, z};
                if (!region.holds(p, r * (1 - 1e-9))) continue;
                maker.add(g, p, d);
                ++placed;
            }
    if (placed == 0)
        throw InputError(fmt::format("{}: grains '{}': the region holds no grain of diameter {} m",
                                     b.origin.at("region"), b.name, d));
}

void read_state(const io::CaseSpec& c, const io::GrainsSpec& b, dem::GrainSet& g) {
    std::filesystem::path p(b.file);
    if (p.is_relative()) p = std::filesystem::path(c.file).parent_path() / p;
    std::ifstream in(p);
    if (!in)
        throw InputError(b.origin.at("file") + ": grains '" + b.name + "': cannot read " +
                         p.string());
    const auto& o = b.file_overrides;
    std::optional<Region> subset;
    if (o.region) subset.emplace(b.region, c.dim);
    const Index before = g.size();
    std::string line;
    std::getline(in, line);
    long row = 1;
    while (std::getline(in, line)) {
        ++row;
        if (line.empty()) continue;
        std::stringstream s(line);
        std::string f[11];
        for (auto& x : f) std::getline(s, x, ',');
        Real v[10];
        try {
            for (int k = 0; k < 10; ++k) v[k] = std::stod(f[k]);
        } catch (const std::exception&) { // invalid_argument, out_of_range
            throw InputError(fmt::format("{}:{}: malformed grain state row (10 numbers and a "
                                         "material name expected)",
                                         p.string(), row));
        }
        for (int k = 0; k < 10; ++k)
            if (!std::isfinite(v[k]))
                throw InputError(
                    fmt::format("{}:{}: column {} is not a finite number", p.string(), row, k + 1));
        if (!(v[9] >= 1e-6))
            throw InputError(
                fmt::format("{}:{}: the diameter {} m is below 1e-6 m", p.string(), row, v[9]));
        const Vec3 x{v[0], v[1], v[2]};
        if (subset && !subset->holds(x, 0)) continue;
        add_grain(c, g, x, o.velocity ? b.velocity : Vec3{v[3], v[4], v[5]},
                  o.angular_velocity ? b.angular_velocity : Vec3{v[6], v[7], v[8]}, v[9],
                  material_index(c, o.material ? b.material : f[10]));
    }
    if (subset && g.size() == before)
        throw InputError(fmt::format("{}: grains '{}': no grain of {} has its centre in the region",
                                     b.origin.at("region"), b.name, p.string()));
}

// A lattice, a single grain or a saved state must not overlap the grains of earlier blocks
// by more than 1 % of its grains' radius (random insertion places grains around them).
void require_clear_of_earlier_blocks(const io::CaseSpec& c, const io::GrainsSpec& b,
                                     const dem::GrainSet& g, Index before) {
    if (before == 0) return;
    Real r_lo = g.radius[0], r_hi = g.radius[0];
    for (Index i = 0; i < before; ++i)
        r_lo = std::min(r_lo, g.radius[std::size_t(i)]),
        r_hi = std::max(r_hi, g.radius[std::size_t(i)]);
    OverlapGrid earlier(r_lo, r_hi, c.dim);
    for (Index i = 0; i < before; ++i) earlier.add(g.pos[std::size_t(i)], g.radius[std::size_t(i)]);
    for (Index i = before; i < g.size(); ++i) {
        const Vec3 p = g.pos[std::size_t(i)];
        const Real r = g.radius[std::size_t(i)];
        if (earlier.overlaps(p, Real(0.99) * r))
            throw InputError(fmt::format(
                "{}: grains '{}': the grain of diameter {:.4g} m at ({:.4g}, {:.4g}, {:.4g}) m "
                "overlaps a grain of an earlier [[grains]] block; move the region, or use "
                "packing = \"random\", which places grains around earlier blocks",
                b.origin.block(), b.name, 2 * r, p.x, p.y, p.z));
    }
}

// A grain may touch a wall, not start inside it: a wall's contact would throw it out at once
// (or, with its centre inside a solid beyond a face's reach, let it fall through).
void require_clear_of_walls(const io::CaseSpec& c, const io::GrainsSpec& b, const dem::GrainSet& g,
                            Index first, Index last, const dem::WallSet& walls) {
    if (last <= first || walls.empty()) return;
    Real rmax = 0;
    for (Index i = first; i < last; ++i) rmax = std::max(rmax, g.radius[std::size_t(i)]);
    const dem::WallProximity near = wall_proximity(c, walls, rmax, false);
    if (near.empty()) return;
    for (Index i = first; i < last; ++i) {
        const Vec3 p = g.pos[std::size_t(i)];
        const Real r = g.radius[std::size_t(i)];
        const dem::WallOverlap o = near.deepest(p, r);
        if (!(o.overlap > max_bed_overlap * r)) continue;
        const std::string how = o.in_solid ? "its centre lies inside"
                                : o.overlap > r
                                    ? "its centre lies behind"
                                    : fmt::format("it sinks {:.3g} m ({:.0f} % of its radius) into",
                                                  o.overlap, 100 * o.overlap / r);
        throw InputError(fmt::format(
            "{}: grains '{}' start inside a wall: the grain of diameter {:.4g} m at ({:.4g}, "
            "{:.4g}, {:.4g}) m: {} wall '{}' (refused above {:.0f} % of a radius: the wall's "
            "contact would throw it out, or let it fall through); move the block's region clear "
            "of the walls (a grain may touch a wall, not cross it)",
            b.origin.at(b.packing == "file"     ? "file"
                        : b.packing == "single" ? "position"
                                                : "region"),
            b.name, 2 * r, p.x, p.y, p.z, how, walls.walls()[std::size_t(o.wall)].name,
            100 * max_bed_overlap));
    }
}

} // namespace

BedOverlap build_grains(const io::CaseSpec& c, dem::GrainSet& g, const dem::WallSet& walls) {
    BedOverlap worst;
    for (const auto& b : c.dem.grains) {
        const Index before = g.size();
        if (b.packing == "file") {
            read_state(c, b, g);
        } else {
            const int mat = material_index(c, b.material);
            if (b.packing == "single")
                GrainMaker(c, b, mat).add(g, b.position, b.size.diameter);
            else if (b.packing == "lattice")
                fill_lattice(c, b, mat, g);
            else
                insert_random(c, b, mat, g);
        }
        if (b.packing != "random") require_clear_of_earlier_blocks(c, b, g, before);
        for (Index i = before; i < g.size(); ++i)
            for (int d = 0; d < 3; ++d) {
                if (c.dim == 2 && d == 1) continue;
                const Real x = d == 0
                                   ? g.pos[std::size_t(i)].x
                                   : (d == 1 ? g.pos[std::size_t(i)].y : g.pos[std::size_t(i)].z);
                if (!(x >= c.domain.lo[d] && x <= c.domain.hi[d]))
                    throw InputError(fmt::format("{}: grains '{}' extend outside the domain in {}",
                                                 b.origin.block(), b.name, "xyz"[d]));
            }
        require_clear_of_walls(c, b, g, before, g.size(), walls);
        const BedOverlap bed = require_bed_rests_on_contacts(c, b, g, before, g.size());
        if (bed.fraction > worst.fraction) worst = bed;
        require_impact_within_contact(c, b, g, before, g.size());
    }
    return worst;
}

dem::WallProximity wall_proximity(const io::CaseSpec& c, const dem::WallSet& walls, Real reach,
                                  bool fixed_only) {
    dem::WallProximity near(walls, reach, c.dim, fixed_only);
    // build_dem_walls adds one wall per [[wall]] block, in order
    for (std::size_t k = 0; k < c.walls.size() && k < walls.walls().size(); ++k) {
        const auto& w = c.walls[k];
        if (w.type != "box") continue;
        Vec3 lo = w.shape.min, hi = w.shape.max;
        if (c.dim == 2) lo.y = -1, hi.y = 1;
        near.add_solid_box(lo, hi, int(k));
    }
    return near;
}

void build_dem_walls(const io::CaseSpec& c, dem::WallSet& walls) {
    for (const auto& w : c.walls) {
        dem::Wall wall;
        wall.name = w.name;
        wall.material = w.material.empty() ? -1 : material_index(c, w.material);
        wall.velocity = w.velocity;
        wall.remove_at = w.remove_at;
        std::vector<dem::WallPrimitive> prims;
        Vec3 lo = w.shape.min, hi = w.shape.max;
        if (c.dim == 2) lo.y = -1, hi.y = 1; // a 2D case is the y = 0 slice of these walls
        if (w.type == "plane") {
            prims.push_back({w.point, {}, {}, w.normal, dem::PrimitiveType::plane, 0});
            wall.origin = w.point;
        } else if (w.type == "box") {
            dem::box_faces(prims, lo, hi, {true, true, true, c.dim == 3});
            wall.origin = Real(0.5) * (lo + hi);
        } else if (w.type == "boxes") {
            // A structure's boxes are solid: rock vertices inside one leave by its nearest
            // exposed face (BodyContacts).
            for (std::size_t k = 0; k < w.boxes.size(); ++k) {
                Vec3 blo = w.boxes[k][0], bhi = w.boxes[k][1];
                if (c.dim == 2) blo.y = -1, bhi.y = 1;
                dem::box_faces(prims, blo, bhi, {true, true, true, c.dim == 3}, std::int32_t(k));
            }
            wall.origin = Real(0.5) * (lo + hi);
        } else if (w.type == "open_tank") {
            dem::box_faces(prims, lo, hi, {true, false, true, c.dim == 3});
            wall.origin = Real(0.5) * (lo + hi);
        } else if (w.type == "channel") {
            dem::box_faces(prims, lo, hi, {true, false, false, c.dim == 3});
            wall.origin = Real(0.5) * (lo + hi);
        } else {
            const auto mesh = TriangleMesh::read_stl(w.shape.file, w.shape.scale, w.shape.offset);
            for (const auto& t : mesh.triangles) {
                if (norm(cross(t.b - t.a, t.c - t.a)) == 0) continue; // degenerate
                prims.push_back(dem::wall_triangle(t.a, t.b, t.c));
            }
            Vec3 mlo, mhi;
            mesh.bounds(mlo, mhi);
            wall.origin = Real(0.5) * (mlo + mhi);
        }
        // Input checks keep boxes resolvable (io/box_extent.hpp); an STL face thinner than
        // round-off would still come without a normal.
        for (const auto& p : prims)
            if (!(std::isfinite(p.n.x) && std::isfinite(p.n.y) && std::isfinite(p.n.z)))
                throw InputError(fmt::format("{}: wall '{}' has a face too small to have a "
                                             "normal (degenerate geometry)",
                                             w.origin.block(), w.name));
        walls.add(wall, prims);
    }
}

void write_grain_state(const std::string& path, const dem::GrainSet& g,
                       const std::vector<dem::Material>& materials) {
    std::ofstream out(path);
    out << "x [m],y [m],z [m],vx [m/s],vy [m/s],vz [m/s],wx [rad/s],wy [rad/s],wz [rad/s],"
           "diameter [m],material\n";
    for (Index i = 0; i < g.size(); ++i) {
        const std::size_t k = std::size_t(i);
        out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
                           "{:.17g},{:.17g},{}\n",
                           g.pos[k].x, g.pos[k].y, g.pos[k].z, g.vel[k].x, g.vel[k].y, g.vel[k].z,
                           g.spin[k].x, g.spin[k].y, g.spin[k].z, 2 * g.radius[k],
                           materials[g.material[k]].name);
    }
}

} // namespace debrisflow::scenario
