#include "debrisflow/scenario/body_geometry.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include "debrisflow/scenario/lattice.hpp"
#include "debrisflow/scenario/stl_mesh.hpp"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <memory>

namespace debrisflow::scenario {

namespace {

using Mat3 = Eigen::Matrix3d;
constexpr Real pi = 3.14159265358979323846;

Eigen::Vector3d ev(Vec3 v) {
    return {v.x, v.y, v.z};
}
Vec3 vec(const Eigen::Vector3d& v) {
    return {v.x(), v.y(), v.z()};
}

// Volume, centroid and inertia per unit density about the centroid (world axes).
struct UnitProps {
    Real volume = 0;
    Vec3 centroid;
    Mat3 inertia = Mat3::Zero();
};

// Inertia of a solid whose second moments about the centroid are C = int r r^T dV.
Mat3 inertia_from_covariance(const Mat3& cov) {
    return cov.trace() * Mat3::Identity() - cov;
}

// Signed distance below the surface (> 0 inside) and outward normal of a shape at p.
struct ShapeField {
    const io::BodySpec& b;
    int dim;
    const TriangleMesh* mesh;

    bool inside(Vec3 p) const { return depth(p).first >= 0; }

    std::pair<Real, Vec3> depth(Vec3 p) const {
        const auto& s = b.shape;
        if (s.type == "box") {
            std::pair<Real, Vec3> best{std::numeric_limits<Real>::max(), {}};
            for (int d = 0; d < 3; ++d) {
                if (dim == 2 && d == 1) continue;
                Vec3 n;
                n[d] = -1;
                if (p[d] - s.min[d] < best.first) best = {p[d] - s.min[d], n};
                n[d] = 1;
                if (s.max[d] - p[d] < best.first) best = {s.max[d] - p[d], n};
            }
            return best;
        }
        if (s.type == "sphere" || (s.type == "cylinder" && dim == 2)) {
            Vec3 r = p - s.center;
            if (dim == 2) r.y = 0;
            const Real d = norm(r);
            return {s.radius - d, d > 0 ? (1 / d) * r : Vec3{0, 0, 1}};
        }
        if (s.type == "cylinder") {
            const Vec3 r = p - s.center;
            const Real along = dot(r, s.axis);
            const Vec3 radial = r - along * s.axis;
            const Real rd = norm(radial);
            std::pair<Real, Vec3> best{s.radius - rd, rd > 0 ? (1 / rd) * radial : Vec3{}};
            if (along < best.first) best = {along, -s.axis};
            if (s.length - along < best.first) best = {s.length - along, s.axis};
            return best;
        }
        if (s.type == "clump") {
            std::pair<Real, Vec3> best{-std::numeric_limits<Real>::max(), {}};
            for (std::size_t k = 0; k < b.clump_centers.size(); ++k) {
                Vec3 r = p - b.clump_centers[k];
                if (dim == 2) r.y = 0;
                const Real d = norm(r);
                if (b.clump_radii[k] - d > best.first)
                    best = {b.clump_radii[k] - d, d > 0 ? (1 / d) * r : Vec3{0, 0, 1}};
            }
            return best;
        }
        // stl: distance to the closest triangle, sign from the parity test
        Real best = std::numeric_limits<Real>::max();
        Vec3 n;
        for (const auto& t : mesh->triangles) {
            const Vec3 q = dem::closest_on_triangle(p, t.a, t.b, t.c);
            const Real d = norm(p - q);
            if (d < best) best = d, n = t.normal();
        }
        return {mesh->contains(p) ? best : -best, n};
    }

    void bounds(Vec3& lo, Vec3& hi) const {
        const auto& s = b.shape;
        if (s.type == "box") {
            lo = s.min, hi = s.max;
        } else if (s.type == "sphere" || s.type == "cylinder") {
            const Real ext = s.type == "cylinder" && dim == 3 ? s.length : 0;
            for (int d = 0; d < 3; ++d) {
                lo[d] = std::min(s.center[d], s.center[d] + ext * s.axis[d]) - s.radius;
                hi[d] = std::max(s.center[d], s.center[d] + ext * s.axis[d]) + s.radius;
            }
        } else if (s.type == "clump") {
            lo = {1e300, 1e300, 1e300}, hi = -1 * lo;
            for (std::size_t k = 0; k < b.clump_centers.size(); ++k)
                for (int d = 0; d < 3; ++d) {
                    lo[d] = std::min(lo[d], b.clump_centers[k][d] - b.clump_radii[k]);
                    hi[d] = std::max(hi[d], b.clump_centers[k][d] + b.clump_radii[k]);
                }
        } else {
            mesh->bounds(lo, hi);
        }
        if (dim == 2) lo.y = -0.5, hi.y = 0.5;
    }
};

UnitProps lattice_props(const ShapeField& f, int dim) {
    Vec3 lo, hi;
    f.bounds(lo, hi);
    const int n = dim == 3 ? 120 : 600;
    Real h = 0;
    for (int d = 0; d < 3; ++d)
        if (dim == 3 || d != 1) h = std::max(h, (hi[d] - lo[d]) / n);
    const Real cell = dim == 3 ? h * h * h : h * h;
    const auto pts = lattice(lo, hi, lo, h, dim, [&](Vec3 p) { return f.inside(p); });
    UnitProps u;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Vec3& p : pts) sum += ev(p);
    u.volume = cell * Real(pts.size());
    u.centroid = vec(sum / Real(pts.size()));
    Mat3 cov = Mat3::Zero();
    for (const Vec3& p : pts) {
        const Eigen::Vector3d r = ev(p - u.centroid);
        cov += r * r.transpose();
    }
    cov *= cell;
    if (dim == 2) cov(1, 1) = u.volume / 12; // 1 m thickness along y
    u.inertia = inertia_from_covariance(cov);
    return u;
}

UnitProps unit_props(const ShapeField& f, int dim) {
    const auto& s = f.b.shape;
    UnitProps u;
    if (s.type == "box") {
        const Vec3 L{s.max.x - s.min.x, dim == 2 ? 1 : s.max.y - s.min.y, s.max.z - s.min.z};
        u.volume = L.x * L.y * L.z;
        u.centroid = Real(0.5) * (s.min + s.max);
        if (dim == 2) u.centroid.y = 0;
        u.inertia.diagonal() << u.volume * (L.y * L.y + L.z * L.z) / 12,
            u.volume * (L.x * L.x + L.z * L.z) / 12, u.volume * (L.x * L.x + L.y * L.y) / 12;
        return u;
    }
    if (s.type == "sphere" || (s.type == "cylinder" && dim == 2)) {
        const Real r = s.radius;
        u.centroid = s.center;
        if (dim == 3) {
            u.volume = 4 * pi * r * r * r / 3;
            u.inertia = Real(0.4) * u.volume * r * r * Mat3::Identity();
        } else { // disc of unit thickness along y
            u.centroid.y = 0;
            u.volume = pi * r * r;
            const Real side = u.volume * (3 * r * r + 1) / 12;
            u.inertia.diagonal() << side, Real(0.5) * u.volume * r * r, side;
        }
        return u;
    }
    if (s.type == "cylinder") {
        const Real r = s.radius, L = s.length;
        u.volume = pi * r * r * L;
        u.centroid = s.center + Real(0.5) * L * s.axis;
        const Real ax = Real(0.5) * u.volume * r * r, perp = u.volume * (3 * r * r + L * L) / 12;
        const Eigen::Vector3d a = ev(s.axis);
        u.inertia = perp * Mat3::Identity() + (ax - perp) * a * a.transpose();
        return u;
    }
    if (s.type == "clump") return lattice_props(f, dim);
    // Closed triangle mesh: signed tetrahedra (origin, a, b, c); second moments of a
    // tetrahedron with a vertex at the origin: C = V/20 (sum v v^T + (sum v)(sum v)^T)
    // (Tonon 2004, J. Math. Stat. 1, 8).
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Mat3 cov = Mat3::Zero();
    for (const auto& t : f.mesh->triangles) {
        const Eigen::Vector3d a = ev(t.a), b = ev(t.b), c = ev(t.c);
        const Real v = a.dot(b.cross(c)) / 6;
        u.volume += v;
        first += v * (a + b + c) / 4;
        const Eigen::Vector3d sum = a + b + c;
        cov += v / 20 *
               (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
    }
    if (!(u.volume > 0))
        throw InputError(fmt::format("{}: body '{}': mesh {} encloses no volume (open mesh or "
                                     "inward normals)",
                                     f.b.origin.at("file"), f.b.name, s.file));
    const Eigen::Vector3d c = first / u.volume;
    u.centroid = vec(c);
    cov -= u.volume * c * c.transpose();
    u.inertia = inertia_from_covariance(cov);
    return u;
}

} // namespace

BuiltBody build_body(const io::BodySpec& b, const io::CaseSpec& c, Real density, Real sph_dp,
                     int layers, const TriangleMesh* given) {
    const int dim = c.dim;
    auto mesh = std::make_shared<TriangleMesh>();
    if (b.shape.type == "stl")
        *mesh =
            given ? *given : TriangleMesh::read_stl(b.shape.file, b.shape.scale, b.shape.offset);
    const ShapeField field{b, dim, mesh.get()};
    const UnitProps u = unit_props(field, dim);
    BuiltBody out;
    out.volume = u.volume;
    out.inside = [spec = b, dim, mesh](Vec3 p) {
        return ShapeField{spec, dim, mesh.get()}.inside(p);
    };
    Real mass = density * u.volume;
    Mat3 inertia = density * u.inertia;
    if (b.mass) {
        inertia *= *b.mass / mass;
        mass = *b.mass;
    }
    Vec3 com = u.centroid;
    if (b.com_offset) {
        const Eigen::Vector3d d = ev(*b.com_offset);
        com = com + *b.com_offset;
        inertia -= mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
    }
    if (b.inertia) {
        const auto& I = *b.inertia;
        inertia << I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2];
    }
    // Principal frame (columns of R); in 2D y stays a principal axis.
    Mat3 R = Mat3::Identity();
    Eigen::Vector3d moments;
    if (dim == 3) {
        Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
        R = eig.eigenvectors();
        moments = eig.eigenvalues();
        if (R.determinant() < 0) R.col(2) *= -1;
    } else {
        Eigen::Matrix2d xz;
        xz << inertia(0, 0), inertia(0, 2), inertia(2, 0), inertia(2, 2);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(xz);
        const Eigen::Vector2d e = eig.eigenvectors().col(0);
        R.col(0) = Eigen::Vector3d(e.x(), 0, e.y());
        R.col(1) = Eigen::Vector3d(0, 1, 0);
        R.col(2) = R.col(0).cross(R.col(1));
        for (int k = 0; k < 3; ++k) moments[k] = R.col(k).dot(inertia * R.col(k));
    }
    for (int k = 0; k < 3; ++k)
        if (!(moments[k] > 0))
            throw InputError(fmt::format("{}: body '{}': inertia tensor is not positive definite "
                                         "(principal moment {:.4g} kg m^2); check its inertia, "
                                         "mass and density",
                                         b.origin.at(b.inertia ? "inertia" : "density"), b.name,
                                         moments[k]));
    const Eigen::Quaterniond eq(R);
    rigid::BodyState& s = out.state;
    s.pos = com;
    s.q = rigid::normalized({eq.w(), eq.x(), eq.y(), eq.z()});
    s.q_user = s.q;
    s.mass = mass;
    s.inv_inertia = {1 / moments[0], 1 / moments[1], 1 / moments[2]};
    s.motion = b.motion == "fixed"        ? rigid::Motion::fixed
               : b.motion == "prescribed" ? rigid::Motion::prescribed
                                          : rigid::Motion::free;
    s.inv_mass = s.motion == rigid::Motion::free ? 1 / mass : 0;
    s.lock_translation = b.lock_translation;
    s.lock_rotation = b.lock_rotation;
    if (dim == 2) s.lock_translation[1] = s.lock_rotation[0] = s.lock_rotation[2] = true;
    s.vel = b.velocity;
    s.prescribed_omega = b.angular_velocity;
    s.ang_mom = rigid::angular_momentum(s.q, b.angular_velocity, s.inv_inertia);

    auto to_body = [&](Vec3 p) { return rigid::rotate_inverse(s.q, p - com); };
    rigid::BodyModel& m = out.model;
    m.name = b.name;
    m.volume = u.volume;
    const auto& sh = b.shape;
    if (sh.type == "box") {
        for (int k = 0; k < (dim == 3 ? 8 : 4); ++k) {
            const Vec3 p{(k & 1) ? sh.max.x : sh.min.x,
                         dim == 2 ? 0 : ((k & 4) ? sh.max.y : sh.min.y),
                         (k & 2) ? sh.max.z : sh.min.z};
            m.vertices.push_back(to_body(p));
        }
    } else if (sh.type == "sphere" || (sh.type == "cylinder" && dim == 2)) {
        Vec3 ctr = sh.center;
        if (dim == 2) ctr.y = 0;
        m.spheres.push_back({to_body(ctr), sh.radius});
    } else if (sh.type == "clump") {
        for (std::size_t k = 0; k < b.clump_centers.size(); ++k) {
            Vec3 ctr = b.clump_centers[k];
            if (dim == 2) ctr.y = 0;
            m.spheres.push_back({to_body(ctr), b.clump_radii[k]});
        }
    } else if (sh.type == "cylinder") {
        Vec3 e1 = std::fabs(sh.axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        e1 = e1 - dot(e1, sh.axis) * sh.axis;
        e1 = (1 / norm(e1)) * e1;
        const Vec3 e2 = cross(sh.axis, e1);
        const int n = 32;
        for (int end = 0; end < 2; ++end)
            for (int k = 0; k < n; ++k) {
                const Real a = 2 * pi * k / n;
                m.vertices.push_back(to_body(sh.center + (end * sh.length) * sh.axis +
                                             (sh.radius * std::cos(a)) * e1 +
                                             (sh.radius * std::sin(a)) * e2));
            }
    } else {
        std::map<std::tuple<Real, Real, Real>, int> seen;
        for (const auto& t : mesh->triangles)
            for (const Vec3& v : {t.a, t.b, t.c})
                if (seen.emplace(std::tuple{v.x, v.y, v.z}, 0).second)
                    m.vertices.push_back(to_body(v));
    }
    Real reach = 0;
    for (const Vec3& v : m.vertices) reach = std::max(reach, norm(v));
    for (const auto& sp : m.spheres) reach = std::max(reach, norm(sp.center) + sp.radius);
    m.bound_radius = {reach, 0, 0};
    Vec3 lo, hi;
    field.bounds(lo, hi);
    Real smallest = std::numeric_limits<Real>::max();
    for (int d = 0; d < 3; ++d)
        if (dim == 3 || d != 1) smallest = std::min(smallest, hi[d] - lo[d]);
    s.contact_radius = b.contact_radius > 0 ? b.contact_radius : Real(0.1) * smallest;
    if (b.track_point) {
        m.track_point = to_body(*b.track_point);
        m.has_track_point = true;
    }
    m.times = b.motion_times;
    m.velocity = b.motion_velocity;
    m.angular_velocity = b.motion_angular_velocity;

    // Shell samples: SPH boundary particles (layers x dp) and distributed-contact spheres.
    auto shell = [&](Real spacing, Real thickness) {
        std::vector<BodySurfacePoint> pts;
        const std::string what = b.origin.block() + ": body '" + b.name + "'";
        for (const Vec3& p : lattice(
                 lo, hi, lo, spacing, dim, [](Vec3) { return true; }, what)) {
            const auto [d, n] = field.depth(p);
            if (d >= 0 && d < thickness) pts.push_back({p, n, d});
        }
        return pts;
    };
    if (sph_dp > 0) {
        out.sph_points = shell(sph_dp, layers * sph_dp);
        if (out.sph_points.empty())
            throw InputError(fmt::format("{}: body '{}' is smaller than dp = {} m: no boundary "
                                         "particles",
                                         b.origin.block(), b.name, sph_dp));
    }
    const Real spacing = c.rigid.contact_spacing > 0 ? c.rigid.contact_spacing : sph_dp;
    if (!m.spheres.empty()) {
        m.samples = m.spheres;
    } else if (spacing > 0) {
        for (const auto& sp : shell(spacing, spacing))
            m.samples.push_back({to_body(sp.p), Real(0.5) * spacing});
    }
    return out;
}

} // namespace debrisflow::scenario
