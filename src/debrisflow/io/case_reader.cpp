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
        t.positive("h_over_dp", kernels::KernelRegistry::visit_name(
                                    p.kernel, []<class K>() { return K::default_h_over_dp; }));
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
    p.no_slip = t.choice("no_slip", {"morris", "mdbc"}, "morris");
    if (p.no_slip == "mdbc") {
        if (p.boundary != "mdbc")
            t.fail("no_slip", "\"mdbc\" mirrors the fluid's velocity at mDBC's ghost nodes; it "
                              "needs sph.boundary = \"mdbc\"");
        const bool walls_slip_free = sph::ViscosityRegistry::visit_name(
            p.viscosity, [&]<class V>() { return V::no_slip_walls; });
        if (!walls_slip_free)
            t.fail("no_slip", "the viscosity model \"" + p.viscosity +
                                  "\" sets no wall velocity (the artificial viscosity uses the "
                                  "wall's own); choose a laminar or rheology model");
    }
    p.pair_loop = t.choice("pair_loop", {"list", "cells"}, "list");
    t.finish();
}

Domain read_domain(const ConfigTable& t, int dim, DomainExitSpec& exit) {
    Domain d;
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

// The common part of a [[probe]] block; its type reads the rest when the probe is made.
ProbeSpec read_probe(const ConfigTable& t, const CaseSpec& c) {
    ProbeSpec p;
    p.origin = t.origin();
    p.name = t.name("name");
    p.type = t.string("type");
    p.every = t.positive("every", 0.001);
    if (c.t_end / p.every > 1e8)
        t.fail("every", fmt::format("would write {:.3g} rows over time.end = {} s (at most 1e8)",
                                    c.t_end / p.every, c.t_end));
    p.table = std::make_shared<const ConfigTable>(t);
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

namespace {

// What the resident backends (exec.backend = "host_resident" or "cuda") run so far. The SPH
// phase: fluid and walls (fixed, moving, removed by remove_at), inlets and outlets, domain exit,
// rigid bodies (their 6-DOF update on the host; rock feeds add them and outlets remove them
// with their particles), DBC and mDBC (with either no-slip), every kernel, viscosity and
// diffusion model, both time schemes. The DEM phase (dem/resident_dem.hpp): spherical grains
// (discs in 2D) with every contact law and rolling model, walls of planes, boxes and triangle
// meshes (fixed, moving, removed by remove_at), rigid bodies as obstacles (their contact
// spheres uploaded when they move, each body's load reduced where the grains are, the bodies
// moved on the host), clumps of grains (one that leaves is removed on the host), settling (on the
// host, before the loop), the domain exit, outlets and grain feeds, every grain probe, FEM solids
// that grains touch (their surface triangles moved with the nodes, the contacts' impulse handed to
// the nodes on the host; the FEM steps on the host). FEM solids in a fluid: their carried
// boundary particles moved, loaded, eroded and exposed where the particles are
// (sph/resident_fem.hpp). Fluid and grains together, with their unresolved coupling
// (coupling/resident_sph_dem.hpp). A case with neither fluid nor grains (FEM solids alone) has
// nothing for them to run and is rejected here, so that `check` rejects it too.
void require_backend_supports(const CaseSpec& c) {
    if (c.backend == "host") return;
    if (c.fluids.empty() && !c.has_dem)
        throw InputError(fmt::format(
            "{}: exec.backend = \"{}\" runs the fluid and the grains where they are; this case "
            "has neither fluid nor grains (use exec.backend = \"host\")",
            c.exec_origin.at("backend"), c.backend));
}

} // namespace

CaseSpec read_case_text(const std::string& text, const std::string& path,
                        const std::vector<std::string>& overrides) {
    CaseSpec c;
    c.file = path;
    // Kept alive by the tables read from it: a probe's block is read when the probe is made.
    auto document = std::make_shared<toml::table>();
    toml::table& doc = *document;
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
        physics.erase("exec"); // a run may continue on another backend
        c.physics_toml = echo_toml(physics);
    }

    ConfigTable root(std::shared_ptr<const toml::table>(document), path);
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

    if (auto exec = root.table("exec")) {
        c.exec_origin = exec->origin();
        c.backend = exec->choice("backend", {"host", "host_resident", "cuda"}, "host");
        exec->finish();
    }

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
        }
        // A prescribed translation: the grains' geometric wall and the fluid's boundary
        // particles move with it (a wall, not a [[structure]]).
        w.velocity = t.vec3("velocity", c.dim, {});
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
    require_backend_supports(c);
    return c;
}

} // namespace debrisflow::io
