#include "debrisflow/io/structure_reader.hpp"
#include "debrisflow/io/box_extent.hpp"
#include "debrisflow/io/named.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::io {

namespace {

constexpr Real pi = 3.14159265358979323846;

using Box = std::array<Vec3, 2>;

Box box(Vec3 lo, Vec3 hi) {
    return {lo, hi};
}

// Slope angle [rad] of a flume table, or nullopt.
std::optional<Real> slope_of(const ConfigTable& t) {
    if (t.has("slope_deg") && t.has("slope_percent"))
        t.fail("slope_deg", "give slope_deg or slope_percent, not both");
    if (t.has("slope_deg")) {
        const Real d = t.real("slope_deg");
        if (d < 0 || d >= 90) t.fail("slope_deg", "must be within [0, 90) degrees");
        return d * pi / 180;
    }
    if (t.has("slope_percent")) {
        const Real p = t.real("slope_percent");
        if (p < 0) t.fail("slope_percent", "must be >= 0");
        return std::atan(p / 100);
    }
    return std::nullopt;
}

// Flume: a bed from x0 to x0 + length (top at z = bed) and, in 3D, side walls at y = 0 and
// y = width up to wall_height; optional transverse ribs of `roughness_height` every
// `roughness_spacing` make a rough bed.
std::vector<Box> flume(const ConfigTable& t, const CaseSpec& c, Real thick) {
    const Real x0 = t.real("start", 0), L = t.positive("length"), bed = t.real("bed", 0);
    const Real H = t.positive("wall_height");
    std::vector<Box> b;
    const Real W = c.dim == 3 ? t.positive("width") : 0;
    b.push_back(box({x0, -thick, bed - thick}, {x0 + L, W + thick, bed}));
    if (c.dim == 3) {
        b.push_back(box({x0, -thick, bed}, {x0 + L, 0, bed + H}));
        b.push_back(box({x0, W, bed}, {x0 + L, W + thick, bed + H}));
    }
    if (t.has("roughness_height")) {
        const Real kh = t.positive("roughness_height"), ks = t.positive("roughness_spacing");
        const Real rib = t.positive("roughness_length", kh);
        const Real ribs = std::floor((L - rib - Real(0.5) * ks) / ks) + 1;
        if (ribs > max_structure_boxes)
            t.fail("roughness_spacing",
                   fmt::format("makes {:.3g} ribs over the {} m flume (at most {})", ribs, L,
                               max_structure_boxes));
        for (long k = 0; k < long(ribs); ++k) {
            const Real x = x0 + (Real(k) + Real(0.5)) * ks;
            b.push_back(box({x, 0, bed}, {x + rib, W, bed + kh}));
        }
    }
    return b;
}

// A wall across the flume at x = position (upstream face), `thickness` along the flow.
Box across(const ConfigTable& t, const CaseSpec& c, Real height) {
    const Real x = t.real("position"), bed = t.real("bed", 0);
    const Real th = t.positive("thickness");
    const Real W = c.dim == 3 ? t.positive("width") : 0;
    return box({x, 0, bed}, {x + th, W, bed + height});
}

// Slit dam: N vertical slits of width s across a dam of width W: N + 1 posts of width
// (W - N s) / (N + 1). Post shapes: "rectangular" (= "P1": a plain rectangular post, the
// thickness of the dam) and "P2" (a rectangular post with an upstream cap `cap_width` wide and
// `cap_depth` deep, which narrows the opening at the upstream face), after the two post types of
// Canelas et al. (2017), whose exact shapes the paper gives only as drawings.
std::vector<Box> slit_dam(const ConfigTable& t, const CaseSpec& c, Real& density) {
    if (c.dim != 3) t.fail("type", "a slit dam needs a 3D case (slits lie across y)");
    const Real x = t.real("position"), bed = t.real("bed", 0);
    const Real th = t.positive("thickness"), H = t.positive("height");
    const Real W = t.positive("width"), s = t.positive("slit_width");
    const long N = t.integer("slits", 0);
    if (N < 1 || 2 * (N + 1) > max_structure_boxes)
        t.fail("slits", fmt::format("required, within 1..{}", max_structure_boxes / 2 - 1));
    const Real post = (W - N * s) / Real(N + 1);
    if (!(post > 0))
        t.fail("slit_width", fmt::format("{} slits of {} m do not fit in {} m", N, s, W));
    const std::string shape = t.choice("post", {"rectangular", "P1", "P2"}, "rectangular");
    Real cap_w = 0, cap_d = 0;
    if (shape == "P2") {
        cap_w = t.positive("cap_width");
        cap_d = t.positive("cap_depth");
        if (cap_w >= post + s) t.fail("cap_width", "must leave an opening between caps");
    }
    density = N * s / W;
    std::vector<Box> b;
    for (long k = 0; k <= N; ++k) {
        const Real y0 = k * (post + s);
        b.push_back(box({x, y0, bed}, {x + th, y0 + post, bed + H}));
        if (shape == "P2") {
            const Real yc = y0 + Real(0.5) * post;
            const Real lo = std::max<Real>(0, yc - Real(0.5) * cap_w);
            const Real hi = std::min<Real>(W, yc + Real(0.5) * cap_w);
            b.push_back(box({x - cap_d, lo, bed}, {x, hi, bed + H}));
        }
    }
    return b;
}

// Staggered baffles: `rows` rows `row_spacing` apart from x = position; row r holds
// `per_row` baffles (one fewer on odd rows, shifted by half the lateral spacing) centred on
// y = center_y, `lateral_spacing` apart; each baffle is size = [along x, across y, height].
std::vector<Box> baffles(const ConfigTable& t, const CaseSpec& c) {
    const Real x0 = t.real("position"), bed = t.real("bed", 0);
    const long rows = t.integer("rows", 0), per_row = t.integer("per_row", 0);
    if (rows < 1 || rows > 10000) t.fail("rows", "required, within 1..10000");
    if (per_row < 1 || per_row > 10000) t.fail("per_row", "required, within 1..10000");
    if (rows * per_row > max_structure_boxes)
        t.fail("per_row", fmt::format("{} rows of {} baffles exceed the {} boxes a case may hold",
                                      rows, per_row, max_structure_boxes));
    const Real dx = rows > 1 ? t.positive("row_spacing") : t.real("row_spacing", 0);
    const Vec3 size = t.vec3("size", 3);
    if (!(size.x > 0 && size.z > 0 && (c.dim == 2 || size.y > 0)))
        t.fail("size", "must be positive [along x, across y, height]");
    std::vector<Box> b;
    if (c.dim == 2) {
        for (long r = 0; r < rows; ++r)
            b.push_back(box({x0 + r * dx, 0, bed}, {x0 + r * dx + size.x, 0, bed + size.z}));
        return b;
    }
    const Real yc = t.real("center_y"), dy = t.positive("lateral_spacing");
    for (long r = 0; r < rows; ++r) {
        const long n = per_row - (r % 2);
        const Real first = yc - Real(0.5) * (n - 1) * dy;
        for (long k = 0; k < n; ++k) {
            const Real y = first + k * dy;
            b.push_back(box({x0 + r * dx, y - Real(0.5) * size.y, bed},
                            {x0 + r * dx + size.x, y + Real(0.5) * size.y, bed + size.z}));
        }
    }
    return b;
}

// Hopper: a bin with vertical walls over [min, max] and a floor with a centred slot
// `orifice` wide across x (3D: the slot spans y); the floor (with `remove_at`) can be a gate.
std::vector<Box> hopper(const ConfigTable& t, const CaseSpec& c, Real thick) {
    Vec3 lo = t.vec3("min", c.dim), hi = t.vec3("max", c.dim);
    for (int d = 0; d < 3; ++d)
        if (!(c.dim == 2 && d == 1) && !(hi[d] > lo[d]))
            t.fail("max", fmt::format("must exceed min in {}", "xyz"[d]));
    const Real orifice = t.real("orifice", 0);
    if (!(orifice >= 0 && orifice < hi.x - lo.x))
        t.fail("orifice",
               fmt::format("must be within [0, {}) m, the hopper's width in x", hi.x - lo.x));
    const Real xm = Real(0.5) * (lo.x + hi.x);
    std::vector<Box> b;
    if (c.dim == 2) lo.y = hi.y = 0;
    const Real ylo = c.dim == 3 ? lo.y - thick : 0, yhi = c.dim == 3 ? hi.y + thick : 0;
    b.push_back(box({lo.x - thick, ylo, lo.z}, {lo.x, yhi, hi.z}));
    b.push_back(box({hi.x, ylo, lo.z}, {hi.x + thick, yhi, hi.z}));
    if (c.dim == 3) {
        b.push_back(box({lo.x, lo.y - thick, lo.z}, {hi.x, lo.y, hi.z}));
        b.push_back(box({lo.x, hi.y, lo.z}, {hi.x, hi.y + thick, hi.z}));
    }
    if (orifice > 0) {
        b.push_back(box({lo.x - thick, ylo, lo.z - thick}, {xm - Real(0.5) * orifice, yhi, lo.z}));
        b.push_back(box({xm + Real(0.5) * orifice, ylo, lo.z - thick}, {hi.x + thick, yhi, lo.z}));
    } else {
        b.push_back(box({lo.x - thick, ylo, lo.z - thick}, {hi.x + thick, yhi, lo.z}));
    }
    return b;
}

} // namespace

Vec3 flume_gravity(const ConfigTable& root, Vec3 gravity) {
    for (const auto& t : root.tables("structure")) {
        if (t.string("type") != "flume") continue;
        if (auto a = slope_of(t)) {
            const Real g = norm(gravity);
            return {g * std::sin(*a), 0, -g * std::cos(*a)};
        }
    }
    return gravity;
}

void read_structures(const ConfigTable& root, CaseSpec& c) {
    const bool fluid = !c.fluids.empty();
    long boxes_so_far = 0;
    for (const auto& t : root.tables("structure")) {
        WallSpec w;
        w.origin = t.origin();
        w.name = t.name("name");
        for (const auto& o : c.walls)
            if (o.name == w.name)
                t.fail("name", "a wall or structure is already named \"" + w.name + "\"");
        w.type = "boxes";
        w.structure =
            t.choice("type", {"flume", "check_dam", "slit_dam", "baffles", "gate", "hopper"});
        if (fluid) {
            w.layers = int(t.integer("layers", long(sph::kernel_layers(c.sph.h, c.dp)), 1,
                                     max_boundary_layers));
        }
        // Plate thickness of flume beds, side walls and hoppers: covers the kernel support
        // (fluid) or 5 % of the structure scale for grains only.
        const Real thick = t.positive("wall_thickness", fluid ? w.layers * c.dp : 0.02);
        if (w.structure == "flume") {
            (void)slope_of(t); // read (applied to gravity by flume_gravity)
            w.boxes = flume(t, c, thick);
        } else if (w.structure == "check_dam") {
            w.boxes = {across(t, c, t.positive("height"))};
        } else if (w.structure == "gate") {
            w.boxes = {across(t, c, t.positive("height"))};
            w.remove_at = t.real("remove_at");
            if (*w.remove_at < 0) t.fail("remove_at", "must be >= 0");
        } else if (w.structure == "slit_dam") {
            w.boxes = slit_dam(t, c, w.slit_density);
        } else if (w.structure == "baffles") {
            w.boxes = baffles(t, c);
        } else {
            w.boxes = hopper(t, c, thick);
        }
        if (w.structure != "gate" && t.has("remove_at")) {
            w.remove_at = t.real("remove_at");
            if (*w.remove_at < 0) t.fail("remove_at", "must be >= 0");
        }
        if (c.has_dem || c.has_bodies()) {
            w.material = t.string("material", "");
            if (!w.material.empty())
                require_named(t, "material", c.dem.materials, w.material, "[[material]]");
        }
        boxes_so_far += long(w.boxes.size());
        if (boxes_so_far > max_structure_boxes)
            t.fail("type", fmt::format("the structures expand into more than {} boxes",
                                       max_structure_boxes));
        for (const auto& b : w.boxes)
            if (const auto why = unresolvable_box(b[0], b[1], c.dim); !why.empty())
                t.fail("type", fmt::format("the {} has a box that {}", w.structure, why));
        // Bounding box (the wall's origin for moments; shape extents).
        w.shape.min = w.boxes[0][0], w.shape.max = w.boxes[0][1];
        for (const auto& b : w.boxes)
            for (int d = 0; d < 3; ++d) {
                w.shape.min[d] = std::min(w.shape.min[d], b[0][d]);
                w.shape.max[d] = std::max(w.shape.max[d], b[1][d]);
            }
        for (int d = 0; d < 3; ++d)
            if (!(c.dim == 2 && d == 1) && c.domain.periodic[d] == false &&
                (w.shape.min[d] < c.domain.lo[d] || w.shape.max[d] > c.domain.hi[d]))
                t.fail("type", fmt::format("the structure ({:.4g}..{:.4g} m in {}) leaves the "
                                           "domain ({:.4g}..{:.4g} m)",
                                           w.shape.min[d], w.shape.max[d], "xyz"[d], c.domain.lo[d],
                                           c.domain.hi[d]));
        t.finish();
        c.walls.push_back(w);
    }
}

} // namespace debrisflow::io
