#include "debrisflow/scenario/build_particles.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/scenario/lattice.hpp"
#include "debrisflow/scenario/stl_mesh.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>

namespace debrisflow::scenario {

namespace {

bool inside_cylinder(const io::ShapeSpec& s, int dim, Vec3 p) {
    const Vec3 r = p - s.center;
    if (dim == 2) return r.x * r.x + r.z * r.z <= s.radius * s.radius;
    const Real along = dot(r, s.axis);
    if (along < 0 || along > s.length) return false;
    const Vec3 radial = r - along * s.axis;
    return dot(radial, radial) <= s.radius * s.radius;
}

std::vector<Vec3> fill_shape(const io::ShapeSpec& s, Real dp, int dim, const std::string& what) {
    if (s.type == "box")
        return lattice(
            s.min, s.max, s.min, dp, dim, [](Vec3) { return true; }, what);
    if (s.type == "cylinder") {
        Vec3 lo, hi;
        for (int d = 0; d < 3; ++d) {
            const Real ext = s.radius + (dim == 3 ? s.length * std::abs(s.axis[d]) : 0);
            lo[d] = s.center[d] - ext;
            hi[d] = s.center[d] + ext;
        }
        return lattice(
            lo, hi, {}, dp, dim, [&](Vec3 p) { return inside_cylinder(s, dim, p); }, what);
    }
    const TriangleMesh mesh = TriangleMesh::read_stl(s.file, s.scale, s.offset);
    Vec3 lo, hi;
    mesh.bounds(lo, hi);
    return lattice(
        lo, hi, {}, dp, dim, [&](Vec3 p) { return mesh.contains(p); }, what);
}

// Surface samples of a mesh with `layers` layers behind it (opposite to the normals).
// A boundary particle with the wall it stands for: unit normal n into the fluid and depth d
// behind the wall surface (used by the no-slip velocity extrapolation of Morris et al. 1997).
struct WallPoint {
    Vec3 p, n;
    Real d;
};

std::vector<WallPoint> mesh_wall(const io::ShapeSpec& s, Real dp, int layers,
                                 const std::string& what) {
    const TriangleMesh mesh = TriangleMesh::read_stl(s.file, s.scale, s.offset);
    double samples = 0; // before sampling: the count must fit in memory
    for (const auto& t : mesh.triangles)
        samples +=
            (std::ceil(norm(t.b - t.a) / dp) + 1) * (std::ceil(norm(t.c - t.a) / dp) + 1) * layers;
    if (!(samples * 64 <= memory_budget_bytes()))
        throw InputError(fmt::format("{}: sampling {} at dp = {} m needs {:.3g} points, more than "
                                     "the memory ({}) allows; coarsen dp or scale the mesh",
                                     what, s.file, dp, samples,
                                     format_bytes(memory_budget_bytes())));
    std::vector<WallPoint> raw;
    for (const auto& t : mesh.triangles) {
        const Vec3 n = t.normal();
        const Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
        const int n1 = std::max(1, int(std::ceil(norm(e1) / dp)));
        const int n2 = std::max(1, int(std::ceil(norm(e2) / dp)));
        for (int i = 0; i <= n1; ++i)
            for (int j = 0; j <= n2; ++j) {
                const Real u = Real(i) / n1, v = Real(j) / n2;
                if (u + v > 1 + 1e-9) continue;
                const Vec3 p = t.a + u * e1 + v * e2;
                for (int k = 0; k < layers; ++k)
                    raw.push_back({p - ((k + 0.5) * dp) * n, n, (k + 0.5) * dp});
            }
    }
    // Thin the samples to about one per 0.8 dp (greedy, hashed by cell).
    const Real gap = Real(0.8) * dp;
    auto cell = [&](Vec3 p, int dx, int dy, int dz) {
        return std::to_string(long(std::floor(p.x / gap)) + dx) + "," +
               std::to_string(long(std::floor(p.y / gap)) + dy) + "," +
               std::to_string(long(std::floor(p.z / gap)) + dz);
    };
    std::unordered_map<std::string, std::vector<Vec3>> hash;
    std::vector<WallPoint> out;
    for (const WallPoint& wp : raw) {
        const Vec3 p = wp.p;
        bool near = false;
        for (int dz = -1; dz <= 1 && !near; ++dz)
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    auto it = hash.find(cell(p, dx, dy, dz));
                    if (it == hash.end()) continue;
                    for (const Vec3& q : it->second)
                        if (dot(q - p, q - p) < gap * gap) near = true;
                }
        if (near) continue;
        out.push_back(wp);
        hash[cell(p, 0, 0, 0)].push_back(p);
    }
    return out;
}

// Every particle of a block must start inside the domain (else the first step would stop the
// run as unstable): names the block and the first point outside.
void require_inside_domain(const std::vector<Vec3>& pts, const io::CaseSpec& c,
                           const std::string& what, const std::string& cause,
                           const std::string& remedy = "move the block") {
    std::size_t outside = 0;
    Vec3 first;
    for (const Vec3& p : pts)
        for (int d = 0; d < 3; ++d)
            if (!(c.dim == 2 && d == 1) && !c.domain.periodic[d] &&
                (p[d] < c.domain.lo[d] || p[d] > c.domain.hi[d])) {
                if (outside++ == 0) first = p;
                break;
            }
    if (outside == 0) return;
    throw InputError(fmt::format(
        "{}: {} of {} particles lie outside the domain (the first at ({:.4g}, {:.4g}, {:.4g}) m; "
        "{}); the domain is ({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g}) m: enlarge "
        "domain.min/domain.max ({}) or {}",
        what, outside, pts.size(), first.x, first.y, first.z, cause, c.domain.lo.x, c.domain.lo.y,
        c.domain.lo.z, c.domain.hi.x, c.domain.hi.y, c.domain.hi.z, c.domain_origin.at("max"),
        remedy));
}

// Normal into the fluid and depth behind the surface of the wall point p.
WallPoint wall_point(const io::WallSpec& w, const io::CaseSpec& c, Vec3 p) {
    if (w.type == "plane") return {p, w.normal, -dot(p - w.point, w.normal)};
    Vec3 lo = w.shape.min, hi = w.shape.max;
    if (w.type == "boxes") // the box holding p (the nearest, for points on shared faces)
        for (const auto& b : w.boxes) {
            bool in = true;
            for (int d = 0; d < 3; ++d)
                if (!(c.dim == 2 && d == 1)) in = in && p[d] >= b[0][d] && p[d] <= b[1][d];
            if (in) {
                lo = b[0], hi = b[1];
                break;
            }
        }
    if (w.type == "open_tank") {
        Vec3 q = p; // nearest point of the inner (fluid) region
        for (int d = 0; d < 3; ++d) {
            if (c.dim == 2 && d == 1) continue;
            q[d] = std::max(q[d], lo[d]);
            if (d != 2) q[d] = std::min(q[d], hi[d]);
        }
        const Vec3 v = q - p;
        const Real dist = norm(v);
        return {p, (1 / dist) * v, dist};
    }
    // solid box: nearest face
    WallPoint best{p, {}, std::numeric_limits<Real>::max()};
    for (int d = 0; d < 3; ++d) {
        if (c.dim == 2 && d == 1) continue;
        Vec3 n;
        n[d] = -1;
        if (p[d] - lo[d] < best.d) best = {p, n, p[d] - lo[d]};
        n[d] = 1;
        if (hi[d] - p[d] < best.d) best = {p, n, hi[d] - p[d]};
    }
    return best;
}

std::vector<WallPoint> build_wall(const io::WallSpec& w, const io::CaseSpec& c) {
    const Real dp = c.dp;
    const std::string what = w.origin.block() + ": wall '" + w.name + "'";
    std::vector<Vec3> pts;
    if (w.type == "open_tank") {
        pts = tank_walls(w.shape.min, w.shape.max, dp, c.dim, w.layers, false, what);
    } else if (w.type == "box" || w.type == "boxes") {
        const Real skin = w.layers * dp;
        const std::vector<std::array<Vec3, 2>> boxes =
            w.type == "box" ? std::vector<std::array<Vec3, 2>>{{w.shape.min, w.shape.max}}
                            : w.boxes;
        // Particles of a box covered by an earlier box are left out (no doubles at joints).
        auto inside = [&](Vec3 p, std::size_t upto) {
            for (std::size_t k = 0; k < upto; ++k) {
                bool in = true;
                for (int d = 0; d < 3; ++d)
                    if (!(c.dim == 2 && d == 1))
                        in = in && p[d] > boxes[k][0][d] && p[d] < boxes[k][1][d];
                if (in) return true;
            }
            return false;
        };
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const Vec3 lo = boxes[k][0], hi = boxes[k][1];
            auto part = lattice(
                lo, hi, lo, dp, c.dim,
                [&](Vec3 p) {
                    Real depth = std::numeric_limits<Real>::max();
                    for (int d = 0; d < 3; ++d) {
                        if (c.dim == 2 && d == 1) continue;
                        depth = std::min({depth, p[d] - lo[d], hi[d] - p[d]});
                    }
                    return depth < skin && !inside(p, k);
                },
                what);
            pts.insert(pts.end(), part.begin(), part.end());
        }
    } else if (w.type == "plane") {
        const Real thick = w.layers * dp;
        // A plane along an axis: only its slab of the domain is visited (same points).
        Vec3 lo = c.domain.lo, hi = c.domain.hi;
        for (int d = 0; d < 3; ++d)
            if (std::abs(w.normal[d]) == 1) {
                const Real a = w.point[d], b = w.point[d] - w.normal[d] * (thick + dp);
                lo[d] = std::max(lo[d], std::min(a, b)), hi[d] = std::min(hi[d], std::max(a, b));
            }
        pts = lattice(
            lo, hi, w.point, dp, c.dim,
            [&](Vec3 p) {
                const Real s = dot(p - w.point, w.normal);
                return s < 0 && s >= -thick;
            },
            what);
    } else {
        if (c.dim == 2) throw InputError(w.origin.at("shape") + ": STL walls need a 3D case");
        return mesh_wall(w.shape, dp, w.layers, what);
    }
    std::vector<WallPoint> out;
    out.reserve(pts.size());
    for (const Vec3& p : pts) out.push_back(wall_point(w, c, p));
    return out;
}

// Where a case's c0 comes from, for a message that says what to raise.
std::string c0_key(const io::CaseSpec& c) {
    return c.c0_coefficient > 0
               ? c.sph_origin.at("c0_coefficient") +
                     fmt::format(" (c0 = coefficient x sqrt(g x reference_depth = {} m))",
                                 c.reference_depth)
               : c.sph_origin.at("c0");
}

// A weakly-compressible fluid at rest is compressed by its own weight: by Tait's law
// rho/rho0 = (1 + gamma rho0 g D / (rho0 c0^2))^(1/gamma) at the bottom of a column D deep.
// Beyond a tenth (c0 below about 2.7 sqrt(g D) for gamma = 7) the run would start as a
// different fluid and stop at once (the health check's bound is 30 %); the usual choice,
// c0 = 10 sqrt(g D), keeps it near 1 %.
void require_weakly_compressible(const io::CaseSpec& c, const models::TaitEos& eos, Real depth,
                                 const std::string& what) {
    const auto& sph = c.sph;
    const Real g = norm(sph.gravity);
    const Real squeeze = eos.density(sph.rho0 * g * depth) / sph.rho0 - 1;
    if (!(squeeze > Real(0.1))) return;
    throw InputError(fmt::format(
        "{}: c0 = {:.4g} m/s is too low for this fluid: its weight alone would compress the "
        "bottom of its {:.4g} m deep column by {:.0f} % (a weakly-compressible fluid should stay "
        "within about 1 %: c0 of at least 10 sqrt(g D) = {:.4g} m/s, and 10 times the fastest "
        "flow speed); raise {}",
        what, sph.c0, depth, 100 * squeeze, 10 * std::sqrt(g * depth), c0_key(c)));
}

// The same bound on a speed the case imposes (a fluid block's initial velocity, an inlet's
// largest inflow, a moving wall): flow brought to rest from speed v is compressed by its
// stagnation pressure rho0 v^2 / 2 (Tait), about Ma^2 / 2 for Mach number Ma = v / c0. Beyond a
// tenth (v above about 0.45 c0) the run is a compressible flow, not the weakly-compressible
// one the model assumes, and stops once the fluid leaves rho0 by 30 %; c0 = 10 v keeps it near
// 0.5 %.
void require_subsonic(const io::CaseSpec& c, const models::TaitEos& eos, Real speed,
                      const std::string& what) {
    const auto& sph = c.sph;
    const Real squeeze = eos.density(Real(0.5) * sph.rho0 * speed * speed) / sph.rho0 - 1;
    if (!(squeeze > Real(0.1))) return;
    throw InputError(fmt::format(
        "{} {:.4g} m/s is too fast for c0 = {:.4g} m/s (Mach {:.2g}): brought to rest, the "
        "flow would compress the fluid by {:.0f} % (a weakly-compressible fluid should stay "
        "within about 1 %: c0 of at least 10 times the fastest flow speed, {:.4g} m/s here); "
        "raise {}",
        what, speed, sph.c0, speed / sph.c0, 100 * squeeze, 10 * speed, c0_key(c)));
}

// A body's surface moves at most at |v| + |w| r (r: the farthest surface particle from its
// centre of mass), for its initial velocity and every row of a prescribed motion's tables.
void require_body_subsonic(const io::CaseSpec& c, const models::TaitEos& eos,
                           const io::BodySpec& spec, const BuiltBody& body) {
    Real reach = 0;
    for (const auto& sp : body.sph_points) reach = std::max(reach, norm(sp.p - body.state.pos));
    Real speed = norm(spec.velocity) + norm(spec.angular_velocity) * reach;
    std::string key = norm(spec.angular_velocity) > 0 && !(norm(spec.velocity) > 0)
                          ? "angular_velocity"
                          : "velocity";
    for (std::size_t i = 0; i < spec.motion_times.size(); ++i) {
        const Real v = i < spec.motion_velocity.size() ? norm(spec.motion_velocity[i]) : 0;
        const Real w =
            i < spec.motion_angular_velocity.size() ? norm(spec.motion_angular_velocity[i]) : 0;
        if (v + w * reach > speed) {
            speed = v + w * reach;
            key = v > 0 ? "motion_velocity" : "motion_angular_velocity";
        }
    }
    require_subsonic(
        c, eos, speed,
        spec.origin.at(key) +
            fmt::format(": body '{}': its surface's largest speed{}", spec.name,
                        reach > 0 && key.find("angular") != std::string::npos
                            ? fmt::format(" (turning, {:.4g} m from its centre of mass)", reach)
                            : ""));
}

} // namespace

ParticleId build_particles(const io::CaseSpec& c, particles::ParticleSet& set,
                           const std::vector<BuiltBody>& bodies) {
    const auto& sph = c.sph;
    // A particle's mass is its initial density times its lattice volume dp^dim (2D: per metre
    // of thickness), so that SPH volumes m/rho match the lattice where the column starts
    // compressed by its own weight.
    const Real volume = sph::lattice_volume(c.dp, c.dim);
    const models::TaitEos eos(sph.rho0, sph.c0, sph.gamma);
    for (const auto& in : c.inlets) {
        const Real peak = *std::max_element(in.discharge.begin(), in.discharge.end());
        require_subsonic(c, eos, peak / in.area(c.dim),
                         in.origin.at("discharge") +
                             fmt::format(": inlet '{}': its largest inflow speed (Q = {:.4g} over "
                                         "{:.4g} m^2)",
                                         in.name, peak, in.area(c.dim)));
    }
    for (const auto& w : c.walls)
        require_subsonic(c, eos, norm(w.velocity), w.origin.at("velocity") + ": the wall's speed");
    for (std::size_t k = 0; k < bodies.size() && k < c.rigid.bodies.size(); ++k)
        require_body_subsonic(c, eos, c.rigid.bodies[k], bodies[k]);
    std::vector<Vec3> boundary;
    std::vector<std::vector<WallPoint>> walls;
    for (const auto& w : c.walls) {
        walls.push_back(build_wall(w, c));
        if (walls.back().empty())
            throw InputError(fmt::format("{}: wall '{}' produced no particles (check its extent "
                                         "against dp = {} m and the domain)",
                                         w.origin.block(), w.name, c.dp));
        std::vector<Vec3> pts;
        for (const WallPoint& wp : walls.back()) pts.push_back(wp.p);
        require_inside_domain(pts, c, w.origin.block() + ": wall '" + w.name + "'",
                              fmt::format("its {} layers of dp = {} m", w.layers, c.dp));
        if (norm(w.velocity) > 0) {
            // A moving wall's particles must stay in the domain (or wrap through a periodic
            // side) while the wall exists: where they are at time.end, or when it is removed.
            const bool removed_first = w.remove_at && *w.remove_at < c.t_end;
            const Real last = removed_first ? *w.remove_at : c.t_end;
            std::vector<Vec3> moved = pts;
            for (Vec3& p : moved) p += last * w.velocity;
            require_inside_domain(moved, c, w.origin.at("velocity"),
                                  fmt::format("where the wall's particles are at {} = {} s",
                                              removed_first ? "remove_at" : "time.end", last),
                                  "slow the wall (or make the direction it moves in periodic)");
        }
        boundary.insert(boundary.end(), pts.begin(), pts.end());
    }
    for (const auto& b : bodies)
        for (const auto& sp : b.sph_points) boundary.push_back(sp.p);
    // A wall's boundary particles are a shell of `layers` around a solid: fluid blocks that
    // overlap a solid wall (a block, a structure, the ground behind a plane, a closed mesh)
    // start outside it, not trapped inside the shell.
    std::vector<std::function<bool(Vec3)>> solid_walls;
    for (const auto& w : c.walls) {
        const bool plane2 = c.dim == 2;
        auto in_box = [plane2](Vec3 p, Vec3 lo, Vec3 hi) {
            for (int d = 0; d < 3; ++d)
                if (!(plane2 && d == 1) && !(p[d] > lo[d] && p[d] < hi[d])) return false;
            return true;
        };
        if (w.type == "box") {
            solid_walls.push_back([=](Vec3 p) { return in_box(p, w.shape.min, w.shape.max); });
        } else if (w.type == "boxes") {
            solid_walls.push_back([=, boxes = w.boxes](Vec3 p) {
                for (const auto& b : boxes)
                    if (in_box(p, b[0], b[1])) return true;
                return false;
            });
        } else if (w.type == "plane") {
            solid_walls.push_back([=](Vec3 p) { return dot(p - w.point, w.normal) < 0; });
        } else if (w.type == "stl") {
            auto mesh = std::make_shared<TriangleMesh>(
                TriangleMesh::read_stl(w.shape.file, w.shape.scale, w.shape.offset));
            Vec3 lo, hi;
            mesh->bounds(lo, hi);
            solid_walls.push_back([=](Vec3 p) {
                return in_box(p, lo, hi) && mesh->contains(p); // the box first: it is cheap
            });
        }
    }
    const Real g = norm(sph.gravity);
    const Vec3 down = g > 0 ? (1 / g) * sph.gravity : Vec3{0, 0, -1};
    struct Column {
        Vec3 lo, hi;
        Real top;
    };
    std::vector<Column> columns;
    for (std::size_t f = 0; f < c.fluids.size(); ++f) {
        const auto& fl = c.fluids[f];
        const std::string what = fl.origin.block() + ": fluid '" + fl.name + "'";
        auto pts =
            remove_near(fill_shape(fl.shape, c.dp, c.dim, what), boundary, Real(0.75) * c.dp);
        std::erase_if(pts, [&](Vec3 p) {
            for (const auto& b : bodies)
                if (b.inside(p)) return true;
            for (const auto& in_wall : solid_walls)
                if (in_wall(p)) return true;
            return false;
        });
        if (pts.empty())
            throw InputError(fmt::format("{}: fluid '{}' produced no particles (shape smaller than "
                                         "dp = {} m, or entirely inside a wall)",
                                         fl.origin.block(), fl.name, c.dp));
        require_inside_domain(pts, c, what, fmt::format("its particles at dp = {} m", c.dp));
        Real top = -std::numeric_limits<Real>::max(); // highest point against gravity
        Real bottom = std::numeric_limits<Real>::max();
        for (const Vec3& p : pts) {
            top = std::max(top, -dot(p, down));
            bottom = std::min(bottom, -dot(p, down));
        }
        top += Real(0.5) * c.dp;
        if (g > 0) require_weakly_compressible(c, eos, top - bottom + Real(0.5) * c.dp, what);
        require_subsonic(c, eos, norm(fl.velocity), fl.origin.at("velocity") + ": its speed");
        if (fl.hydrostatic && g > 0) {
            Column col{pts[0], pts[0], top};
            for (const Vec3& p : pts)
                for (int d = 0; d < 3; ++d) {
                    col.lo[d] = std::min(col.lo[d], p[d]);
                    col.hi[d] = std::max(col.hi[d], p[d]);
                }
            columns.push_back(col);
        }
        for (const Vec3& p : pts) {
            Real rho = sph.rho0;
            if (fl.hydrostatic && g > 0) rho = eos.density(sph.rho0 * g * (top + dot(p, down)));
            set.add(p, fl.velocity, rho, rho * volume, particles::Kind::fluid, std::int16_t(f));
        }
    }
    // Boundary particles under a hydrostatic column start with that column's pressure
    // (within the column's plan extent), so the fluid does not sink at the first step.
    const Real reach = 2 * sph.h;
    for (std::size_t w = 0; w < walls.size(); ++w)
        for (const WallPoint& wp : walls[w]) {
            const Vec3 p = wp.p;
            Real pressure = 0;
            for (const auto& col : columns)
                if (p.x >= col.lo.x - reach && p.x <= col.hi.x + reach && p.y >= col.lo.y - reach &&
                    p.y <= col.hi.y + reach && col.top + dot(p, down) > 0)
                    pressure = std::max(pressure, sph.rho0 * g * (col.top + dot(p, down)));
            const Real rho = eos.density(pressure);
            // a moving wall's particles carry its velocity (SphSolver translates them)
            set.add(p, c.walls[w].velocity, rho, rho * volume, particles::Kind::boundary,
                    std::int16_t(w));
            set.set_wall(set.size() - 1, wp.n, wp.d);
        }
    // Body boundary particles: the hydrostatic pressure of the column they start in.
    const ParticleId first_body = set.size() > 0 ? set.id.back() + 1 : 0;
    for (const auto& b : bodies)
        for (const auto& sp : b.sph_points) {
            Real pressure = 0;
            for (const auto& col : columns)
                if (sp.p.x >= col.lo.x && sp.p.x <= col.hi.x && sp.p.y >= col.lo.y &&
                    sp.p.y <= col.hi.y && col.top + dot(sp.p, down) > 0)
                    pressure = std::max(pressure, sph.rho0 * g * (col.top + dot(sp.p, down)));
            const Real rho = eos.density(pressure);
            set.add(sp.p, {}, rho, rho * volume, particles::Kind::boundary, std::int16_t(-1));
            set.set_wall(set.size() - 1, sp.n, sp.depth);
        }
    return first_body;
}

} // namespace debrisflow::scenario
