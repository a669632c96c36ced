#include "debrisflow/scenario/clump_template.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/scenario/body_geometry.hpp"
#include <algorithm>
#include <cmath>

namespace debrisflow::scenario {

namespace {
constexpr Real pi = 3.14159265358979323846;
}

ClumpTemplate ClumpTemplate::from(const io::GrainsSpec& b, const io::CaseSpec& c) {
    io::BodySpec body;
    body.name = b.name;
    body.origin = b.origin;
    body.shape.type = "clump";
    body.clump_centers = b.clump_centers;
    body.clump_radii = b.clump_radii;
    const BuiltBody unit = build_body(body, c, 1, 0, 0);
    ClumpTemplate t;
    t.dim = c.dim;
    // volume-equivalent diameter of the shape as given, then everything scaled to 1
    const Real d_eq =
        c.dim == 3 ? std::cbrt(6 * unit.volume / pi) : std::sqrt(4 * unit.volume / pi);
    if (!(d_eq > 0))
        throw InputError(b.origin.at("clump") + ": grains '" + b.name +
                         "': the clump has no volume");
    const Real s = 1 / d_eq;
    for (const auto& sp : unit.model.spheres) {
        t.centers.push_back(s * sp.center);
        t.radii.push_back(s * sp.radius);
        t.reach = std::max(t.reach, s * (norm(sp.center) + sp.radius));
    }
    t.volume = unit.volume * std::pow(s, c.dim);
    const Vec3 ii = unit.state.inv_inertia;
    const Real scale = std::pow(s, c.dim + 2); // moments ~ length^(dim + 2)
    t.inertia = {scale / ii.x, scale / ii.y, scale / ii.z};
    return t;
}

void add_clump(const io::CaseSpec& c, dem::GrainSet& g, const ClumpTemplate& shape, Vec3 x, Vec3 v,
               Vec3 w, Real d, int mat, rigid::Quat q) {
    const Real rho = c.dem.materials[std::size_t(mat)].density;
    const Real t = c.dim == 2 ? c.dem.thickness : 1;
    if (c.dim == 2) x.y = 0, v.y = 0, w = {0, w.y, 0};
    const Real mass = rho * t * shape.volume * std::pow(d, c.dim);
    const Real moment_scale = rho * t * std::pow(d, c.dim + 2);
    Vec3 inv_i{1 / (moment_scale * shape.inertia.x), 1 / (moment_scale * shape.inertia.y),
               1 / (moment_scale * shape.inertia.z)};
    if (c.dim == 2) inv_i.x = inv_i.z = 0; // turns about y only
    Real weights = 0;
    for (Real r : shape.radii) weights += std::pow(r, c.dim);
    const Real inv_i_max = std::max({inv_i.x, inv_i.y, inv_i.z});
    std::vector<std::uint32_t> ids;
    std::vector<Vec3> offsets;
    for (std::size_t k = 0; k < shape.radii.size(); ++k) {
        const Vec3 offset = d * shape.centers[k];
        const Vec3 lever = rigid::rotate(q, offset);
        const Real r = d * shape.radii[k];
        const Real share = mass * std::pow(shape.radii[k], c.dim) / weights;
        ids.push_back(g.next_id());
        // the member's own moment is not used (the clump turns); 1/I_min keeps it finite
        g.set_spin(
            g.add(x + lever, v + cross(w, lever), r, share, 1 / inv_i_max, std::uint8_t(mat)), w);
        offsets.push_back(offset);
    }
    g.clumps.add(x, v, w, q, mass, inv_i, ids, offsets);
}

rigid::Quat random_orientation(std::mt19937_64& rng, int dim) {
    std::uniform_real_distribution<Real> u(0, 1);
    if (dim == 2) return rigid::axis_angle({0, 1, 0}, 2 * pi * u(rng));
    // Shoemake 1992: uniform on the unit 3-sphere
    const Real u1 = u(rng), u2 = 2 * pi * u(rng), u3 = 2 * pi * u(rng);
    const Real a = std::sqrt(1 - u1), b = std::sqrt(u1);
    return rigid::normalized(
        {a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3)});
}

} // namespace debrisflow::scenario
