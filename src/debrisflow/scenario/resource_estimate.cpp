#include "debrisflow/scenario/resource_estimate.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/io/named.hpp"
#include "debrisflow/sph/sph_models.hpp"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>

namespace debrisflow::scenario {

namespace {

constexpr double pi = 3.14159265358979323846;

// Lattice points of spacing dp in [lo, hi] (x-z in 2D), as a double: no overflow.
double lattice_points(Vec3 lo, Vec3 hi, double dp, int dim) {
    double n = 1;
    for (int d = 0; d < 3; ++d) {
        if (dim == 2 && d == 1) continue;
        n *= std::floor(std::max(0.0, double(hi[d] - lo[d])) / dp) + 1;
    }
    return n;
}

double box_volume(Vec3 lo, Vec3 hi, int dim) {
    double v = 1;
    for (int d = 0; d < 3; ++d)
        if (!(dim == 2 && d == 1)) v *= std::max(0.0, double(hi[d] - lo[d]));
    return v;
}

// Volume of the shell of thickness t inside the box [lo, hi].
double shell_volume(Vec3 lo, Vec3 hi, double t, int dim) {
    const Vec3 s{Real(t), Real(t), Real(t)};
    return box_volume(lo, hi, dim) - box_volume(lo + s, hi - s, dim);
}

double cell(double dp, int dim) {
    return dim == 3 ? dp * dp * dp : dp * dp;
}

// Bounding box of a fluid, wall or grain region (cylinder and box; false for STL).
bool shape_bounds(const io::ShapeSpec& s, int dim, Vec3& lo, Vec3& hi) {
    if (s.type == "box" || s.type == "open_tank" || s.type == "channel") {
        lo = s.min, hi = s.max;
        return true;
    }
    if (s.type == "cylinder" || s.type == "sphere") {
        for (int d = 0; d < 3; ++d) {
            const Real ext = s.radius + (dim == 3 ? s.length * std::abs(s.axis[d]) : 0);
            lo[d] = s.center[d] - ext, hi[d] = s.center[d] + ext;
        }
        return true;
    }
    return false;
}

double grain_volume(double d, const io::CaseSpec& c) {
    return c.dim == 3 ? pi / 6 * d * d * d : pi / 4 * d * d * c.dem.thickness;
}

// A representative diameter for counting grains of a given mass or volume: the median,
// within the window [min, max] the sizes are drawn from.
double median_diameter(const io::SizeSpec& s) {
    if (s.distribution == "lognormal") return std::clamp(s.d50, s.min, s.max);
    if (s.distribution == "sieve") {
        for (std::size_t i = 1; i < s.sieve_sizes.size(); ++i)
            if (s.sieve_passing[i] >= 50) return std::clamp(s.sieve_sizes[i], s.min, s.max);
        return std::clamp(s.sieve_sizes.back(), s.min, s.max);
    }
    return s.diameter > 0 ? s.diameter : s.min;
}

double material_density(const io::CaseSpec& c, const std::string& name) {
    const auto* m = io::find_named(c.dem.materials, name);
    return m && m->density > 0 ? m->density : 2650;
}

// Volume delivered by a hydrograph over [0, t_end], the last value held.
double delivered(const std::vector<Real>& times, const std::vector<Real>& q, double t_end) {
    if (q.empty()) return 0;
    double v = 0;
    for (std::size_t k = 0; k + 1 < times.size() && times[k] < t_end; ++k) {
        const double b = std::min<double>(times[k + 1], t_end);
        const double qb = q[k] + (q[k + 1] - q[k]) * (b - times[k]) / (times[k + 1] - times[k]);
        v += 0.5 * (q[k] + qb) * (b - times[k]);
    }
    if (t_end > times.back()) v += q.back() * (t_end - times.back());
    return v;
}

} // namespace

double sph_bytes_per_particle(int dim, double support_over_dp, bool density_gradient) {
    // Particle fields (21 Real + kind + group + id) and one more field while reordering (they
    // are permuted one at a time); integrator copies (7 Real); the positions at the last list
    // build, the pressure terms, sound speeds and volumes (6 Real); grid arrays; the half pair list
    // (neighbors/pair_list.hpp): half the neighbours within support + skin (1.1 support) plus a
    // quarter, and 8 per row, 4 bytes each, with its row indexes (start, owner, count, row,
    // rows, touched, mask: 33 B); the scatter loops' per-thread sums (4 Real, 2 threads).
    // Charged to every particle, fluid or wall, though only fluid particles have rows: a wall
    // stands in for the fluid-wall pairs of the fluid beside it. Measured against it: 740 B per
    // particle (full neighbourhoods, 3D, h = sqrt(3) dp: the container case at dp = 0.02 m,
    // 1.6 M fluid and 1.2 M wall particles) against 1,011 B estimated.
    const double reach = 1.1 * support_over_dp;
    const double neighbours =
        dim == 3 ? 4.0 / 3.0 * pi * reach * reach * reach : pi * reach * reach;
    const double list = (0.5 * neighbours * 1.25 + 8) * 4 + 33;
    // the density gradients (3 Real) and their pass's buffers: 5 (2D) or 9 (3D) Real per
    // particle and thread instead of the force pass's 4
    const double gradient =
        density_gradient ? 3 * sizeof(Real) + (dim == 3 ? 5 : 1) * sizeof(Real) * 2 : 0;
    const double fields = (21 + 1) * sizeof(Real) + 1 + 2 + 8, solver = (7 + 6) * sizeof(Real);
    return fields + solver + 3 * 4 + list + 4 * sizeof(Real) * 2 + gradient;
}

double bytes_per_grain(const io::CaseSpec& c) {
    // 19 Real + material + id, and about 12 contact slots (index, key, 6-Real history); the
    // device's contact layout (dem.contact_pass = "slots") adds per slot its 9-Real result,
    // a flag and a reverse-index entry.
    const double slot_pass = c.dem.params.slot_contacts ? 12 * (9 * sizeof(Real) + 1 + 4) : 0;
    // The resident loop in host memory (exec.backend = "host_resident") holds its own copy of
    // the grains and their contact state, and about 12 grain and 8 wall slots per grain in the
    // device's layout, each with the previous rebuild's row, its 9-Real result and a flag, and
    // a reverse-index entry per grain slot: 3,129 B, above the 2,127 B per grain measured on
    // box100k and flume30.
    const double resident = c.backend == "host_resident" && c.fluids.empty()
                                ? 19 * sizeof(Real) + 5 + 17 * sizeof(Real) +
                                      20 * (2 * (8 + 3 * sizeof(Real)) + 9 * sizeof(Real) + 1) +
                                      12 * 8
                                : 0;
    return 19 * sizeof(Real) + 5 + 12 * (8 + 6 * sizeof(Real)) + 6 * sizeof(Real) + slot_pass +
           resident;
}

double ResourceEstimate::total_bytes() const {
    double b = 0;
    for (const auto& i : items) b += i.bytes;
    return b;
}

ResourceEstimate estimate_resources(const io::CaseSpec& c) {
    ResourceEstimate e;
    const bool fluid = !c.fluids.empty();
    const double dp = c.dp;
    const double per_particle =
        fluid ? sph_bytes_per_particle(c.dim, 2 * c.sph.h / dp,
                                       sph::diffusion_needs_density_gradient(c.sph.diffusion))
              : 0;
    auto add = [&](std::string what, std::string where, double count, double bytes_each) {
        e.items.push_back({std::move(what), std::move(where), count, count * bytes_each});
    };
    if (fluid) {
        for (const auto& f : c.fluids) {
            Vec3 lo, hi;
            if (!shape_bounds(f.shape, c.dim, lo, hi)) continue;
            double v = box_volume(lo, hi, c.dim);
            if (f.shape.type == "cylinder")
                v = c.dim == 3 ? pi * f.shape.radius * f.shape.radius * f.shape.length
                               : pi * f.shape.radius * f.shape.radius;
            add("fluid '" + f.name + "'", f.origin.at(f.shape.type == "box" ? "max" : "radius"),
                v / cell(dp, c.dim), per_particle);
        }
        for (const auto& in : c.inlets)
            add("fluid entering through inlet '" + in.name + "' by the end time",
                in.origin.at("discharge"),
                delivered(in.times, in.discharge, c.t_end) / cell(dp, c.dim), per_particle);
        for (const auto& w : c.walls) {
            const double t = w.layers * dp;
            double v = 0;
            if (w.type == "box") {
                v = shell_volume(w.shape.min, w.shape.max, t, c.dim);
            } else if (w.type == "boxes") {
                for (const auto& b : w.boxes) v += shell_volume(b[0], b[1], t, c.dim);
            } else if (w.type == "open_tank") {
                Vec3 lo = w.shape.min, hi = w.shape.max;
                for (int d = 0; d < 3; ++d) lo[d] -= Real(t), hi[d] += d == 2 ? 0 : Real(t);
                v = box_volume(lo, hi, c.dim) - box_volume(w.shape.min, w.shape.max, c.dim);
            } else if (w.type == "plane") {
                int a = 0;
                for (int d = 1; d < 3; ++d)
                    if (std::abs(w.normal[d]) > std::abs(w.normal[a])) a = d;
                const double across = box_volume(c.domain.lo, c.domain.hi, c.dim) /
                                      std::max(1e-300, double(c.domain.hi[a] - c.domain.lo[a]));
                v = across * t / std::abs(w.normal[a]);
            }
            add("wall '" + w.name + "'", w.origin.at(w.type == "plane" ? "normal" : "max"),
                v / cell(dp, c.dim), per_particle);
        }
        // The SPH cell grid: cells of one kernel support over the domain.
        const double support = 2 * c.sph.h;
        add("the neighbour grid over domain.min to domain.max (cells of 2h)",
            c.domain_origin.at("max"), lattice_points(c.domain.lo, c.domain.hi, support, c.dim),
            16);
    }
    for (const auto& b : c.rigid.bodies) {
        Vec3 lo, hi;
        if (b.shape.type == "clump") {
            lo = {1e300, 1e300, 1e300}, hi = -1 * lo;
            for (std::size_t k = 0; k < b.clump_centers.size(); ++k)
                for (int d = 0; d < 3; ++d) {
                    lo[d] = std::min(lo[d], b.clump_centers[k][d] - b.clump_radii[k]);
                    hi[d] = std::max(hi[d], b.clump_centers[k][d] + b.clump_radii[k]);
                }
        } else if (!shape_bounds(b.shape, c.dim, lo, hi)) {
            continue;
        }
        const std::string key = b.shape.type == "sphere" || b.shape.type == "cylinder" ? "radius"
                                : b.shape.type == "clump"                              ? "spheres"
                                                                                       : "max";
        if (fluid && b.layers > 0)
            add("boundary particles of body '" + b.name + "'", b.origin.at(key),
                shell_volume(lo, hi, b.layers * dp, c.dim) / cell(dp, c.dim), per_particle);
        const double spacing = c.rigid.contact_spacing > 0 ? c.rigid.contact_spacing : dp;
        if (spacing > 0 && b.shape.type != "clump")
            add("contact spheres of body '" + b.name + "'", b.origin.at(key),
                shell_volume(lo, hi, spacing, c.dim) / cell(spacing, c.dim), 64);
    }
    for (const auto& g : c.dem.grains) {
        const double d = median_diameter(g.size);
        const double rho = material_density(c, g.material);
        double n = 0;
        std::string key = "count";
        if (g.packing == "single") {
            n = 1;
        } else if (g.packing == "random") {
            n = g.count > 0 ? double(g.count) : g.mass / (rho * grain_volume(d, c));
            key = g.count > 0 ? "count" : "mass";
        } else if (g.packing == "file") {
            // A saved state row (10 numbers and a name) takes about 100 bytes of the file.
            std::filesystem::path f(g.file);
            if (f.is_relative()) f = std::filesystem::path(c.file).parent_path() / f;
            std::error_code ec;
            const auto bytes = std::filesystem::file_size(f, ec);
            n = ec ? 0 : double(bytes) / 100;
            key = "file";
        } else if (g.packing == "lattice") {
            Vec3 lo, hi;
            if (!shape_bounds(g.region, c.dim, lo, hi)) continue;
            n = lattice_points(lo, hi, d * (1 + g.gap), c.dim);
            key = "diameter";
        }
        // a clump (size: its volume-equivalent diameter) is as many grains as it has spheres;
        // on a lattice it takes at least its diameter (an upper bound on the count)
        const double members = g.clump_radii.empty() ? 1 : double(g.clump_radii.size());
        add("grains '" + g.name + "'", g.origin.at(key), n * members, bytes_per_grain(c));
    }
    for (const auto& f : c.dem.feeds) {
        const double d = median_diameter(f.size);
        add("grains released by feed '" + f.name + "' by the end time", f.origin.at("discharge"),
            delivered(f.times, f.discharge, c.t_end) / grain_volume(d, c), bytes_per_grain(c));
    }
    for (const auto& s : c.fem.solids) {
        if (s.mesh == "gmsh") continue;
        const double nodes =
            double(s.divisions[0] + 1) * (s.divisions[1] + 1) * double(s.divisions[2] + 1);
        add("FEM solid '" + s.name + "'", s.origin.at("divisions"), nodes, 64 * 8 + 200);
    }
    return e;
}

void require_within_budget(const ResourceEstimate& e) {
    const double budget = memory_budget_bytes(), total = e.total_bytes();
    if (total <= budget) return;
    std::vector<ResourceItem> items = e.items;
    std::sort(items.begin(), items.end(),
              [](const auto& a, const auto& b) { return a.bytes > b.bytes; });
    const ResourceItem& top = items.front();
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(3, items.size()); ++k)
        list += fmt::format("\n  {}: {} needs about {:.3g} items, {}", items[k].where,
                            items[k].what, items[k].count, format_bytes(items[k].bytes));
    throw InputError(fmt::format(
        "{}: the case needs about {} of memory, more than the {} available (the machine's "
        "memory, or --max-memory); the largest parts:{}\ncoarsen dp or the grain size, or "
        "shrink the regions",
        top.where, format_bytes(total), format_bytes(budget), list));
}

void require_lattice_within_budget(Vec3 lo, Vec3 hi, Real dp, int dim, const std::string& what) {
    const double n = lattice_points(lo, hi, dp, dim);
    // A lattice point costs its Vec3 here and, kept, a particle later: 32 bytes is the least.
    if (n * 32 <= memory_budget_bytes() && n < 4e9) return;
    throw InputError(fmt::format("{}: a lattice of spacing {:.4g} m over ({:.4g}, {:.4g}, {:.4g}) "
                                 "to ({:.4g}, {:.4g}, {:.4g}) m has {:.3g} points, more than the "
                                 "memory ({}) allows; coarsen the spacing or shrink the region",
                                 what, dp, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, n,
                                 format_bytes(memory_budget_bytes())));
}

} // namespace debrisflow::scenario
