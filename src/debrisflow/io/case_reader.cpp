#include "debrisflow/core/error.hpp"
#include "debrisflow/io/box_extent.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/io/config_table.hpp"
#include "debrisflow/io/dem_reader.hpp"
#include "debrisflow/io/fem_reader.hpp"
#include "debrisflow/io/flow_reader.hpp"
#include "debrisflow/io/named.hpp"
#include "debrisflow/io/rigid_reader.hpp"
#include "debrisflow/io/structure_reader.hpp"
#include "debrisflow/io/toml_echo.hpp"
#include "debrisflow/kernels/kernel.hpp"
#include "debrisflow/sph/sph_models.hpp"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace debrisflow::io {

ShapeSpec read_shape(const ConfigTable& t, int dim, const std::vector<std::string>& allowed) {
    ShapeSpec s;
    s.type = t.choice("shape", allowed);
    if (s.type == "box" || s.type == "open_tank" || s.type == "channel") {
        s.min = t.vec3("min", dim);
        s.max = t.vec3("max", dim);
        for (int d = 0; d < 3; ++d) {
            if (dim == 2 && d == 1) continue;
            if (!(s.max[d] > s.min[d]))
                t.fail("max", fmt::format("must exceed min in {} ({} <= {})", "xyz"[d], s.max[d],
                                          s.min[d]));
        }
        if (const auto why = unresolvable_box(s.min, s.max, dim); !why.empty())
            t.fail("max", "the box " + why);
    } else if (s.type == "cylinder") {
        s.center = t.vec3("center", dim);
        s.radius = t.positive("radius");
        if (dim == 3) {
            s.axis = t.vec3("axis", dim, {0, 0, 1});
            if (norm(s.axis) == 0) t.fail("axis", "must be a non-zero vector");
            s.axis = (1 / norm(s.axis)) * s.axis;
            s.length = t.positive("length");
        }
    } else if (s.type == "stl") {
        std::string f = t.string("file");
        std::filesystem::path p(f);
        if (p.is_relative()) p = std::filesystem::path(t.file()).parent_path() / p;
        if (!std::filesystem::exists(p)) t.fail("file", "mesh file not found: " + p.string());
        s.file = p.string();
        s.scale = t.positive("scale", 1);
        s.offset = t.vec3("offset", dim, {});
    }
    return s;
}

namespace {

// Slurry rheology keys of [sph] (bingham, herschel_bulkley, mu_i); nu is the Newtonian base.
void read_sph(const ConfigTable& t, CaseSpec& c) {
    auto& p = c.sph;
    p.dim = c.dim;
    p.dp = c.dp;
    p.kernel = t.choice("kernel", kernels::KernelRegistry::names(), "wendland_c2");
    const Real h_over_dp =
        t.positive("h_over_dp", p.kernel == "cubic_spline" ? std::sqrt(3.0) : 1.5);
    if (h_over_dp < 0.5 || h_over_dp > 4)
        t.fail("h_over_dp", "must be within [0.5, 4] (usual: 1.2 to 2; each particle then has "
                            "a few dozen to a few hundred neighbours)");
    p.h = h_over_dp * c.dp;
    p.rho0 = t.positive("rho0", 1000);
    p.gamma = t.positive("gamma", 7);
    if (t.has("c0") && t.has("c0_coefficient"))
        t.fail("c0", "give either c0 or c0_coefficient (with reference_depth), not both");
    if (t.has("c0")) {
        p.c0 = t.positive("c0");
    } else {
        c.c0_coefficient = t.positive("c0_coefficient");
        c.reference_depth = t.positive("reference_depth");
        p.c0 = c.c0_coefficient * std::sqrt(norm(p.gravity) * c.reference_depth);
        if (!(p.c0 > 0)) t.fail("c0_coefficient", "gravity is zero; give c0 directly");
    }
    p.viscosity = t.choice("viscosity", sph::ViscosityRegistry::names(), "artificial");
    // alpha and boundary_factor are read for every model, so that sweeps may switch models
    // with --set; each model reads its own keys in its from_config.
    models::ViscosityContext ctx;
    ctx.rho0 = p.rho0;
    ctx.h = p.h;
    ctx.alpha = t.real("alpha", 0.01);
    if (ctx.alpha < 0) t.fail("alpha", "must be >= 0");
    ctx.boundary_factor = t.real("boundary_factor", 1);
    if (ctx.boundary_factor < 0) t.fail("boundary_factor", "must be >= 0");
    p.viscosity_model =
        sph::ViscosityRegistry::visit_name(p.viscosity, [&]<class V>() -> sph::Viscosity {
            if constexpr (V::requires_nu)
                p.nu = t.positive("nu");
            else
                p.nu = t.has("nu") ? t.positive("nu") : 0;
            ctx.nu = p.nu;
            return V::from_config(t, ctx);
        });
    p.diffusion = t.choice("diffusion", sph::DiffusionRegistry::names(), "fourtakas");
    p.delta = t.real("delta", 0.1); // read for every model so sweeps may switch models
    if (p.delta < 0 || p.delta > 1) t.fail("delta", "must be within [0, 1]");
    p.cfl = t.positive("cfl", 0.2);
    if (p.cfl > 1) t.fail("cfl", "must be <= 1");
    p.reorder_every = int(t.integer("reorder_every", 1, 0, 1000000000));
    // Without gravity in the fluid there is no hydrostatic pressure; immersed bodies then get
    // its exact resultant, the buoyancy rho0 V g (sedimentation in closed boxes).
    c.fluid_gravity = t.boolean("fluid_gravity", true);
    p.boundary_min_pressure = t.real("boundary_min_pressure", 0);
    if (p.boundary_min_pressure > 0) t.fail("boundary_min_pressure", "must be <= 0 [Pa]");
    p.boundary = t.choice("boundary", {"dbc", "mdbc"}, "dbc");
    t.finish();
}

sph::Domain read_domain(const ConfigTable& t, int dim, DomainExitSpec& exit) {
    sph::Domain d;
    d.lo = t.vec3("min", dim);
    d.hi = t.vec3("max", dim);
    if (dim == 2) d.lo.y = d.hi.y = 0;
    for (int k = 0; k < 3; ++k)
        if (!(dim == 2 && k == 1) && !(d.hi[k] > d.lo[k]))
            t.fail("max", fmt::format("must exceed min in {}", "xyz"[k]));
        else if (!std::isfinite(d.hi[k] - d.lo[k]))
            t.fail("max",
                   fmt::format("the extent in {} overflows (not a finite number)", "xyz"[k]));
    if (t.has("periodic")) {
        for (const auto& s : t.strings("periodic")) {
            if (s == "x")
                d.periodic[0] = true;
            else if (s == "y" && dim == 3)
                d.periodic[1] = true;
            else if (s == "z")
                d.periodic[2] = true;
            else
                t.fail("periodic",
                       "expected a list of \"x\", \"y\" (3D) or \"z\", got \"" + s + "\"");
        }
    }
    exit.policy = t.choice("exit", {"remove", "stop"}, "remove");
    exit.warn_fraction = t.real("exit_warn_fraction", 0.01);
    if (!(exit.warn_fraction >= 0 && exit.warn_fraction <= 1))
        t.fail("exit_warn_fraction", "must be in [0, 1] (a fraction of the phase's mass)");
    t.finish();
    return d;
}

// A point probe outside the domain would read nothing (p = 0) for the whole run.
void require_in_domain(const ConfigTable& t, const std::string& key, Vec3 p, const CaseSpec& c) {
    for (int d = 0; d < 3; ++d)
        if (!(c.dim == 2 && d == 1) && (p[d] < c.domain.lo[d] || p[d] > c.domain.hi[d]))
            t.fail(key, fmt::format("({:.4g}, {:.4g}, {:.4g}) m lies outside the domain ({:.4g}, "
                                    "{:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g}) m",
                                    p.x, p.y, p.z, c.domain.lo.x, c.domain.lo.y, c.domain.lo.z,
                                    c.domain.hi.x, c.domain.hi.y, c.domain.hi.z));
}

ProbeSpec read_probe(const ConfigTable& t, const CaseSpec& c) {
    ProbeSpec p;
    p.origin = t.origin();
    p.name = t.name("name");
    p.type = t.choice("type", {"pressure",         "gauge",        "velocity",       "front",
                               "wall_force",       "section",      "kinetic_energy", "runup",
                               "mass_flux",        "body",         "discharge",      "trapping",
                               "deposit",          "flow_section", "fluid_runup",    "pressure_map",
                               "fem_displacement", "fem_force",    "fem_face_load",  "domain_exit",
                               "hazard_map"});
    p.every = t.positive("every", 0.001);
    if (c.t_end / p.every > 1e8)
        t.fail("every", fmt::format("would write {:.3g} rows over time.end = {} s (at most 1e8)",
                                    c.t_end / p.every, c.t_end));
    const bool fluid_probe = p.type == "pressure" || p.type == "velocity" || p.type == "gauge" ||
                             p.type == "front" || p.type == "flow_section" ||
                             p.type == "fluid_runup" || p.type == "hazard_map";
    if (fluid_probe && c.fluids.empty()) t.fail("type", "a " + p.type + " probe needs a fluid");
    if (p.type == "pressure_map" && c.fluids.empty() && !c.has_dem && !c.has_bodies())
        t.fail("type", "a pressure_map probe needs a fluid, grains or bodies");
    const bool grain_probe = p.type == "section" || p.type == "kinetic_energy" ||
                             p.type == "runup" || p.type == "mass_flux";
    if (grain_probe && !c.has_dem) t.fail("type", "a " + p.type + " probe needs [[grains]]");
    if (p.type == "fem_force") {
        if (!c.has_fem()) t.fail("type", "a fem_force probe needs a [[solid]]");
    } else if (p.type == "fem_face_load") {
        if (!c.has_fem()) t.fail("type", "a fem_face_load probe needs a [[solid]]");
        p.set = t.string("set");
        const auto dot = p.set.find('.');
        if (dot == std::string::npos ||
            std::none_of(c.fem.solids.begin(), c.fem.solids.end(),
                         [&](const auto& s) { return s.name == p.set.substr(0, dot); }))
            t.fail("set", "needs \"<solid>.<set>\" naming a [[solid]] (e.g. \"dam.upstream\")");
        p.normal = t.vec3("normal", c.dim);
        if (!(norm(p.normal) > 0)) t.fail("normal", "must be a non-zero vector");
        const std::string axis = t.choice("axis", {"x", "y", "z"}, "z");
        p.axis = axis == "x" ? 0 : axis == "y" ? 1 : 2;
        p.panels_u = int(t.integer("bins", 5, 1, 100));
    } else if (p.type == "fem_displacement") {
        if (!c.has_fem()) t.fail("type", "a fem_displacement probe needs a [[solid]]");
        if (t.has("set")) {
            p.set = t.string("set");
            const auto dot = p.set.find('.');
            const std::string solid = p.set.substr(0, dot);
            if (std::none_of(c.fem.solids.begin(), c.fem.solids.end(),
                             [&](const auto& s) { return s.name == solid; }))
                t.fail("set", "no [[solid]] named \"" + solid +
                                  "\" (a set is \"<solid>.<set>\" or \"<solid>\")");
        } else {
            p.position = t.vec3("position", c.dim);
        }
    } else if (p.type == "body") {
        p.body = t.string("body");
        if (std::none_of(c.rigid.bodies.begin(), c.rigid.bodies.end(),
                         [&](const auto& b) { return b.name == p.body; }))
            t.fail("body", "no [[body]] named \"" + p.body + "\"");
    } else if (p.type == "gauge") {
        // A gauge stands at a plan position: (x, y) in 3D, (x) in 2D; a vertical coordinate,
        // if given, is ignored (the gauge scans the whole height of the domain).
        const auto v = t.reals("position");
        const std::size_t plan = c.dim == 3 ? 2 : 1;
        if (v.size() != plan && v.size() != plan + 1)
            t.fail("position", c.dim == 3 ? "expected [x, y] (or [x, y, z], z ignored)"
                                          : "expected [x] (or [x, z], z ignored)");
        p.position = c.dim == 3 ? Vec3{v[0], v[1], c.domain.lo.z} : Vec3{v[0], 0, c.domain.lo.z};
        require_in_domain(t, "position", p.position, c);
    } else if (p.type == "pressure" || p.type == "velocity") {
        p.position = t.vec3("position", c.dim);
        require_in_domain(t, "position", p.position, c);
    } else if (p.type == "section" || p.type == "kinetic_energy") {
        p.min = t.vec3("min", c.dim);
        p.max = t.vec3("max", c.dim);
        if (c.dim == 2) p.min.y = -1e30, p.max.y = 1e30;
        for (int d = 0; d < 3; ++d)
            if (!(p.max[d] > p.min[d])) t.fail("max", "must exceed min");
        if (p.type == "section") p.bed = t.real("bed", p.min.z);
    } else if (p.type == "flow_section" || p.type == "deposit") {
        p.min = t.vec3("min", c.dim);
        p.max = t.vec3("max", c.dim);
        if (c.dim == 2) p.min.y = -1e30, p.max.y = 1e30;
        for (int d = 0; d < 3; ++d)
            if (!(p.max[d] > p.min[d])) t.fail("max", "must exceed min");
        p.bed = t.real("bed", p.min.z);
    } else if (p.type == "hazard_map") {
        // A plan grid over [min, max] (2D: along x); the columns count fluid between min.z
        // and max.z; depths from `bed` (default min.z).
        p.min = t.vec3("min", c.dim);
        p.max = t.vec3("max", c.dim);
        if (c.dim == 2) p.min.y = 0, p.max.y = 1;
        for (int d = 0; d < 3; ++d)
            if (!(p.max[d] > p.min[d])) t.fail("max", "must exceed min");
        p.bed = t.real("bed", p.min.z);
        const auto n = t.reals("cells");
        const std::size_t plan = c.dim == 3 ? 2 : 1;
        if (n.size() != plan || std::any_of(n.begin(), n.end(), [](Real v) {
                return !(v >= 1 && v <= 10000 && v == std::floor(v));
            }))
            t.fail("cells", c.dim == 3 ? "expected [n_x, n_y], whole numbers from 1 to 10000"
                                       : "expected [n_x], a whole number from 1 to 10000");
        p.panels_u = int(n[0]);
        p.panels_v = c.dim == 3 ? int(n[1]) : 1;
    } else if (p.type == "trapping") {
        if (!c.has_dem && !c.has_bodies())
            t.fail("type", "a trapping probe needs grains or bodies");
        p.position = t.vec3("upstream", c.dim);
        p.point_b = t.vec3("downstream", c.dim);
        p.normal = t.vec3("normal", c.dim, {1, 0, 0});
        if (norm(p.normal) == 0) t.fail("normal", "must be a non-zero vector");
        p.normal = (1 / norm(p.normal)) * p.normal;
        if (!(dot(p.point_b - p.position, p.normal) > 0))
            t.fail("downstream", "must lie downstream (along normal) of the upstream plane");
        const auto w = t.reals("window");
        if (w.size() != 2 || !(w[1] > w[0]) || w[0] < 0)
            t.fail("window", "expected [t_start, t_end] with t_end > t_start >= 0 [s]");
        p.t0 = w[0], p.t1 = w[1];
    } else if (p.type == "mass_flux" || p.type == "discharge") {
        p.position = t.vec3("point", c.dim);
        p.normal = t.vec3("normal", c.dim);
        if (norm(p.normal) == 0) t.fail("normal", "must be a non-zero vector");
        p.normal = (1 / norm(p.normal)) * p.normal;
    } else if (p.type == "domain_exit") {
        if (c.domain_exit.policy != "remove")
            t.fail("type", "a domain_exit probe counts what domain.exit = \"remove\" removes; "
                           "domain.exit is \"stop\"");
    } else if (p.type == "front") {
        // "+x" (or "x"): the largest x of the fluid; "-x": the smallest (a surge running
        // towards -x)
        const std::string a =
            t.choice("axis", {"x", "y", "z", "+x", "+y", "+z", "-x", "-y", "-z"}, "x");
        p.axis = a.back() == 'x' ? 0 : (a.back() == 'y' ? 1 : 2);
        p.normal = {};
        p.normal[p.axis] = a.front() == '-' ? -1 : 1;
        if (c.dim == 2 && p.axis == 1) t.fail("axis", "2D cases flow in the x-z plane");
    } else {
        p.wall = t.string("wall");
        bool found = false;
        for (const auto& w : c.walls) found = found || w.name == p.wall;
        if (!found) t.fail("wall", "no wall named \"" + p.wall + "\"");
        if (p.type == "wall_force") {
            p.normal = t.vec3("normal", c.dim, {});
            if (norm(p.normal) > 0) p.normal = (1 / norm(p.normal)) * p.normal;
            p.approach = t.string("approach", "");
            p.boulder = t.string("boulder", "");
            if ((!p.approach.empty() || !p.boulder.empty()) && norm(p.normal) == 0)
                t.fail("normal", "design companions need the wall's normal (the load direction)");
            if (!p.approach.empty()) {
                p.width = c.dim == 2 ? t.positive("width", 1) : t.positive("width");
                p.rho = t.real("rho", 0);
                if (p.rho < 0) t.fail("rho", "must be >= 0 (0: the approach probe's density)");
                if (std::none_of(c.probes.begin(), c.probes.end(), [&](const auto& q) {
                        return q.name == p.approach &&
                               (q.type == "flow_section" || q.type == "section");
                    }))
                    t.fail("approach", "no flow_section or section probe named \"" + p.approach +
                                           "\" above this one");
            }
            if (!p.boulder.empty()) {
                p.k_c = t.positive("k_c", 0.1);
                if (std::none_of(c.probes.begin(), c.probes.end(), [&](const auto& q) {
                        return q.name == p.boulder && q.type == "body";
                    }))
                    t.fail("boulder", "no body probe named \"" + p.boulder + "\" above this one");
            }
        } else if (p.type == "pressure_map") {
            const auto& w = *std::find_if(c.walls.begin(), c.walls.end(),
                                          [&](const auto& w) { return w.name == p.wall; });
            if (w.type == "plane" || w.type == "stl")
                t.fail("wall", "a pressure map tiles a face of the wall's bounding box; wall \"" +
                                   p.wall + "\" is a " + w.type +
                                   " (use a box, an open_tank or a [[structure]])");
            const std::string a = t.choice("axis", {"x", "y", "z"}, "x");
            p.axis = a == "x" ? 0 : (a == "y" ? 1 : 2);
            p.normal = t.vec3("normal", c.dim, {});
            if (!(std::abs(norm(p.normal) - 1) < 1e-9) || std::abs(p.normal[p.axis]) != 1)
                t.fail("normal", "must be the unit vector along axis, pointing into the fluid");
            const auto n = t.reals("panels");
            if (n.size() != 2 || n[0] < 1 || n[1] < 1)
                t.fail("panels", "expected [n_u, n_v] (>= 1) panels over the face");
            p.panels_u = int(n[0]), p.panels_v = int(n[1]);
            if (c.dim == 2) p.panels_v = 1; // one row across the unit width
        } else {
            p.bed = t.real("bed", c.domain.lo.z);
        }
    }
    t.finish();
    return p;
}

} // namespace

CaseSpec read_case(const std::string& path, const std::vector<std::string>& overrides) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path + ": is a folder, not a case file (give the .toml file)");
    if (!std::filesystem::exists(path, ec)) throw InputError(path + ": file not found");
    if (std::filesystem::file_size(path, ec) > (64u << 20))
        throw InputError(path + ": larger than 64 MiB; a case file is a few kilobytes of TOML");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    return read_case_text(text.str(), path, overrides);
}

CaseSpec read_case_text(const std::string& text, const std::string& path,
                        const std::vector<std::string>& overrides) {
    CaseSpec c;
    c.file = path;
    toml::table doc;
    try {
        doc = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& src = e.source();
        throw InputError(
            fmt::format("{}:{}:{}: {}", path, src.begin.line, src.begin.column, e.description()));
    }
    for (const auto& o : overrides) apply_override(doc, o);
    c.resolved_toml = echo_toml(doc);
    {
        toml::table physics = doc;
        physics.erase("output");
        if (auto* time = physics["time"].as_table()) time->erase("end");
        c.physics_toml = echo_toml(physics);
    }

    ConfigTable root(doc, path, "");
    c.origin = root.origin();
    c.name = root.has("name") ? root.name("name")
                              : file_safe_name(std::filesystem::path(path).stem().string());
    c.dim = int(root.integer("dimensions", 2, 2, 3));
    // dp is the fluid particle spacing; a grains-only case may omit it.
    const bool fluid_input = !root.tables("fluid").empty() || !root.tables("inlet").empty();
    c.dp = fluid_input ? root.positive("dp") : root.positive("dp", 0);

    auto time = root.table("time");
    if (!time) root.fail("time", "missing required table [time] with key 'end'");
    c.time_origin = time->origin();
    c.t_end = time->positive("end");
    c.scheme = time->choice("scheme", {"symplectic", "verlet"}, "symplectic");
    c.verlet_euler_every = int(time->integer("verlet_euler_every", 40, 1, 1000000));
    time->finish();

    auto output = root.table("output");
    if (output) {
        c.vtk = output->boolean("vtk", true);
        c.vtk_every = output->real("vtk_every", 0);
        if (c.vtk_every < 0) output->fail("vtk_every", "must be >= 0");
        if (c.vtk_every > 0 && c.t_end / c.vtk_every > 1e5)
            output->fail("vtk_every", fmt::format("would write {:.3g} frames over time.end = {} s "
                                                  "(at most 1e5)",
                                                  c.t_end / c.vtk_every, c.t_end));
        c.progress_seconds = output->positive("progress_seconds", 2);
        c.checkpoint_every = output->real("checkpoint_every", 0);
        if (!(c.checkpoint_every >= 0)) output->fail("checkpoint_every", "must be >= 0 (s)");
        if (c.checkpoint_every > 0 && c.t_end / c.checkpoint_every > 1e5)
            output->fail("checkpoint_every",
                         fmt::format("would write {:.3g} checkpoints over time.end = {} s (at "
                                     "most 1e5)",
                                     c.t_end / c.checkpoint_every, c.t_end));
        c.checkpoint_wall = output->real("checkpoint_wall", 0);
        if (!(c.checkpoint_wall >= 0)) output->fail("checkpoint_wall", "must be >= 0 (minutes)");
        output->finish();
    }

    Vec3 gravity{0, 0, -9.81};
    auto physics = root.table("physics");
    if (physics) {
        gravity = physics->vec3("gravity", c.dim, gravity);
        physics->finish();
    }
    if (c.dim == 2) gravity.y = 0;
    gravity = flume_gravity(root, gravity); // a flume's slope tilts gravity
    c.sph.gravity = gravity;

    auto domain = root.table("domain");
    if (!domain) root.fail("domain", "missing required table [domain] with min and max");
    c.domain_origin = domain->origin();
    c.domain = read_domain(*domain, c.dim, c.domain_exit);

    auto fluid_tables = root.tables("fluid");
    auto sph = root.table("sph");
    if (fluid_input) {
        if (!sph) root.fail("sph", "missing table [sph] (the case has [[fluid]] or [[inlet]])");
        c.sph_origin = sph->origin();
        read_sph(*sph, c);
    } else if (sph) {
        sph->fail("c0", "[sph] given but the case has no [[fluid]]");
    }
    c.sph.gravity = c.fluid_gravity ? gravity : Vec3{};

    for (const auto& t : fluid_tables) {
        FluidSpec f;
        f.origin = t.origin();
        f.name = t.name("name");
        f.shape = read_shape(t, c.dim, {"box", "cylinder", "stl"});
        f.velocity = t.vec3("velocity", c.dim, {});
        f.hydrostatic = t.boolean("hydrostatic", true);
        t.finish();
        c.fluids.push_back(f);
    }
    read_inlets(root, c);
    read_outlets(root, c);
    read_dem(root, c);
    c.dem.params.gravity = gravity;
    read_rigid(root, c);
    read_fem(root, c, gravity);
    if (c.fluids.empty() && !c.has_dem && !c.has_bodies() && !c.has_fem())
        root.fail("fluid", "a case needs [[fluid]], [[grains]], [[body]] or [[solid]] blocks");

    for (const auto& t : root.tables("wall")) {
        WallSpec w;
        w.origin = t.origin();
        w.name = t.name("name");
        for (const auto& o : c.walls)
            if (o.name == w.name) t.fail("name", "two walls are named \"" + w.name + "\"");
        w.type = t.choice("shape", {"box", "open_tank", "channel", "plane", "stl"});
        if (w.type == "channel" && !c.fluids.empty())
            t.fail("shape", "channel walls are geometric (DEM) only; use open_tank with a fluid");
        if (w.type == "plane") {
            w.point = t.vec3("point", c.dim);
            w.normal = t.vec3("normal", c.dim);
            if (c.dim == 2) w.normal.y = 0;
            if (norm(w.normal) == 0) t.fail("normal", "must be a non-zero vector");
            w.normal = (1 / norm(w.normal)) * w.normal;
        } else {
            w.shape = read_shape(t, c.dim, {"box", "open_tank", "channel", "stl"});
        }
        if (!c.fluids.empty()) {
            w.layers = int(t.integer("layers", long(sph::kernel_layers(c.sph.h, c.dp)), 1,
                                     max_boundary_layers));
        }
        if (c.has_dem || c.has_bodies()) {
            w.material = t.string("material", "");
            if (!w.material.empty())
                require_named(t, "material", c.dem.materials, w.material, "[[material]]");
            w.velocity = t.vec3("velocity", c.dim, {});
        }
        if (t.has("remove_at")) {
            w.remove_at = t.real("remove_at");
            if (*w.remove_at < 0) t.fail("remove_at", "must be >= 0");
        }
        t.finish();
        c.walls.push_back(w);
    }

    read_structures(root, c);

    for (const auto& t : root.tables("probe")) {
        c.probes.push_back(read_probe(t, c));
        for (std::size_t i = 0; i + 1 < c.probes.size(); ++i)
            if (c.probes[i].name == c.probes.back().name)
                t.fail("name", "two probes are named \"" + c.probes.back().name + "\"");
    }
    root.finish();
    return c;
}

} // namespace debrisflow::io
