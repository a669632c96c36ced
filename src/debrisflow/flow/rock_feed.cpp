#include "debrisflow/flow/rock_feed.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/rigid/quaternion_k.hpp"
#include "debrisflow/scenario/body_geometry.hpp"
#include "debrisflow/scenario/build_grains.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::flow {

namespace {

constexpr Real pi = 3.14159265358979323846;

// Enclosed volume (signed tetrahedra) and its centroid.
Real volume_and_centroid(const scenario::TriangleMesh& m, Vec3& centroid) {
    Real v = 0;
    Vec3 first{};
    for (const auto& t : m.triangles) {
        const Real dv = dot(t.a, cross(t.b, t.c)) / 6;
        v += dv;
        first = first + (dv / 4) * (t.a + t.b + t.c);
    }
    centroid = v != 0 ? (1 / v) * first : Vec3{};
    return v;
}

Real area(const scenario::TriangleMesh& m) {
    Real a = 0;
    for (const auto& t : m.triangles) a += Real(0.5) * norm(cross(t.b - t.a, t.c - t.a));
    return a;
}

scenario::TriangleMesh transformed(const scenario::TriangleMesh& m, auto&& f) {
    scenario::TriangleMesh out = m;
    for (auto& t : out.triangles) t = {f(t.a), f(t.b), f(t.c)};
    return out;
}

} // namespace

Real sphericity(const scenario::TriangleMesh& mesh) {
    Vec3 c;
    const Real v = volume_and_centroid(mesh, c);
    return std::cbrt(pi) * std::pow(6 * v, Real(2) / 3) / area(mesh);
}

RockFeed::RockFeed(const io::FeedSpec& spec, const io::CaseSpec& c)
    : SolidFeed(spec, c), material_(scenario::material_index(c, spec.material)),
      density_(c.dem.materials[std::size_t(material_)].density),
      layers_(spec.layers > 0 ? spec.layers : sph::kernel_layers(c.sph.h, c.dp)),
      sph_dp_(c.fluids.empty() ? 0 : c.dp) {
    for (const auto& file : spec.rocks) {
        const auto raw = scenario::TriangleMesh::read_stl(file, 1, {});
        Vec3 ctr;
        const Real v = volume_and_centroid(raw, ctr);
        if (!(v > 0))
            throw InputError(fmt::format("{}: feed '{}': rock shape {} encloses no volume (open "
                                         "mesh or inward normals)",
                                         c.file, spec.name, file));
        const Real to_unit = 1 / std::cbrt(6 * v / pi); // equivalent diameter 1
        Shape s;
        s.mesh = transformed(raw, [&](Vec3 p) { return to_unit * (p - ctr); });
        s.sphericity = sphericity(s.mesh);
        shapes_.push_back(std::move(s));
    }
}

scenario::TriangleMesh RockFeed::make_rock(Real d, Real& ratio) {
    std::uniform_real_distribution<Real> u(0, 1);
    auto& rng = sizes_.rng();
    const Shape& shape = shapes_[std::size_t(u(rng) * Real(shapes_.size())) % shapes_.size()];
    // Stretch (a, b, 1/(ab)): ln a, ln b uniform in +-0.4 (up to 1.5x); kept when the
    // sphericity is within the bound, else drawn again (the shape itself after 100 tries).
    Vec3 stretch{1, 1, 1};
    ratio = 1;
    for (int k = 0; k < 100; ++k) {
        const Real a = std::exp(Real(0.8) * (u(rng) - Real(0.5)));
        const Real b = std::exp(Real(0.8) * (u(rng) - Real(0.5)));
        const Vec3 s{a, b, 1 / (a * b)};
        const Real r = sphericity(transformed(shape.mesh,
                                              [&](Vec3 p) {
                                                  return Vec3{s.x * p.x, s.y * p.y, s.z * p.z};
                                              })) /
                       shape.sphericity;
        if (std::fabs(r - 1) <= spec_.sphericity_tolerance) {
            stretch = s;
            ratio = r;
            break;
        }
    }
    // Uniform random orientation (Shoemake 1992).
    const Real u1 = u(rng), u2 = 2 * pi * u(rng), u3 = 2 * pi * u(rng);
    const rigid::Quat q{std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2),
                        std::sqrt(1 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3)};
    return transformed(shape.mesh, [&](Vec3 p) {
        return d * rigid::rotate(q, Vec3{stretch.x * p.x, stretch.y * p.y, stretch.z * p.z});
    });
}

RockFeed::GrainsNear RockFeed::near_in(const dem::GrainSet& grains) {
    return [&grains](const FeedReach& region) {
        std::vector<std::pair<Vec3, Real>> near;
        for (std::size_t i = 0; i < grains.pos.size(); ++i)
            if (region.near(grains.pos[i], grains.radius[i]))
                near.push_back({grains.pos[i], grains.radius[i]});
        return near;
    };
}

void RockFeed::apply(rigid::BodySolver& bodies, const GrainsNear& grains,
                     const probes::FluidReader* fluid, Real t, Real dt) {
    accrue(t, dt);
    if (owed_ < piece_volume(next_d_)) return;
    // Grains and SPH particles near the region (possible overlaps), gathered once per batch.
    const Real reach = 2 * spec_.size.max + case_.dp;
    auto near_region = [&](Vec3 p) {
        for (int k = 0; k < 3; ++k)
            if (!(p[k] > spec_.min[k] - reach && p[k] < spec_.max[k] + reach)) return false;
        return true;
    };
    std::vector<std::pair<Vec3, Real>> near;
    if (grains) // a superset (FeedReach also counts the grain's radius), then this feed's test
        for (const auto& [p, r] : grains(FeedReach{spec_.min, spec_.max, reach, false}))
            if (near_region(p)) near.push_back({p, r});
    if (fluid) {
        const Vec3 grow{reach, reach, reach};
        for (const auto& r :
             fluid->rows(probes::RowSelection::particles_in(spec_.min - grow, spec_.max + grow)))
            if (near_region(r.x)) near.push_back({r.x, Real(0.5) * case_.dp});
    }
    std::uniform_real_distribution<Real> u(0, 1);
    auto& rng = sizes_.rng();
    constexpr int tries_per_rock = 200;
    while (owed_ >= piece_volume(next_d_)) {
        Real ratio, mass = 0;
        const scenario::TriangleMesh rock = make_rock(next_d_, ratio);
        Real r = 0;
        for (const auto& tri : rock.triangles)
            r = std::max({r, norm(tri.a), norm(tri.b), norm(tri.c)});
        bool placed = false;
        for (int k = 0; k < tries_per_rock && !placed; ++k) {
            Vec3 p;
            bool fits = true;
            for (int a = 0; a < 3; ++a) {
                fits = fits && spec_.max[a] - spec_.min[a] > 2 * r;
                p[a] = spec_.min[a] + r + u(rng) * (spec_.max[a] - spec_.min[a] - 2 * r);
            }
            if (!fits) break;
            bool free = true;
            for (const auto& [x, rx] : near)
                if (norm(p - x) < r + rx) {
                    free = false;
                    break;
                }
            for (std::size_t b = 0; free && b < bodies.bodies().size(); ++b)
                if (norm(p - bodies.bodies()[b].pos) < r + bodies.models()[b].bound_radius.x)
                    free = false;
            if (!free) continue;
            io::BodySpec spec;
            spec.name = fmt::format("{}_{}", spec_.name, count_ + 1);
            spec.material = spec_.material;
            spec.shape.type = "stl";
            spec.shape.file = spec_.rocks.front();
            spec.velocity = spec_.velocity;
            spec.density = density_;
            const auto placed_mesh = transformed(rock, [&](Vec3 x) { return x + p; });
            auto built =
                scenario::build_body(spec, case_, density_, sph_dp_, layers_, &placed_mesh);
            built.state.material = material_;
            std::vector<rigid::ShellPoint> shell;
            for (const auto& sp : built.sph_points) shell.push_back({sp.p, sp.n, sp.depth});
            const Real m_particle = case_.sph.rho0 * sph::lattice_volume(case_.dp, case_.dim);
            mass = built.state.mass;
            bodies.add_body(built.state, std::move(built.model), shell, case_.sph.rho0, m_particle);
            placed = true;
        }
        if (!placed) break; // region full: the debt waits for the next step
        released(piece_volume(next_d_), mass);
    }
}

} // namespace debrisflow::flow
