#include "debrisflow/fem/fem_surface.hpp"
#include "debrisflow/dem/wall_geometry_k.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace debrisflow::fem {

namespace {

// Element faces (local nodes, outward right-hand order; 2D edges with -1).
const std::vector<std::vector<int>>& faces_of(ElementType t) {
    static const std::vector<std::vector<int>> hex = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                      {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    static const std::vector<std::vector<int>> tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    // tet10: corners a, b, c, then the edge nodes of ab, bc, ca (VTK edge order 01 12 02 03 13 23).
    static const std::vector<std::vector<int>> tet10 = {
        {0, 2, 1, 6, 5, 4}, {0, 1, 3, 4, 8, 7}, {1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}};
    static const std::vector<std::vector<int>> quad = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    switch (t) {
    case ElementType::hex8:
        return hex;
    case ElementType::quad4:
        return quad;
    case ElementType::tet10:
        return tet10;
    default:
        return tet;
    }
}

} // namespace

std::vector<SurfaceFacet> boundary_facets(const FemSolver& fem) {
    std::map<std::vector<std::int32_t>, std::pair<SurfaceFacet, std::vector<std::int32_t>>> seen;
    std::vector<std::vector<std::int32_t>> twice;
    for (std::size_t s = 0; s < fem.solids().size(); ++s) {
        const auto& so = fem.solids()[s];
        const int nn = nodes_of(so.type);
        for (std::size_t e = 0; e < so.volume.size(); ++e) {
            if (so.eroded[e]) continue;
            const std::int32_t* c = &so.conn[e * std::size_t(nn)];
            for (const auto& f : faces_of(so.type)) {
                std::vector<std::int32_t> ordered, key;
                for (int a : f) ordered.push_back(c[a]);
                key.assign(ordered.begin(), ordered.begin() + (f.size() == 6 ? 3 : f.size()));
                std::sort(key.begin(), key.end());
                auto it = seen.find(key);
                if (it != seen.end()) {
                    seen.erase(it);
                    continue;
                }
                seen[key] = {{std::int32_t(s), std::int32_t(e), {0, 0, 0}}, ordered};
            }
        }
    }
    std::vector<SurfaceFacet> out;
    for (const auto& [key, v] : seen) {
        const auto& [facet, o] = v;
        SurfaceFacet f = facet;
        if (o.size() == 2) {
            f.nodes = {o[0], o[1], -1};
            out.push_back(f);
        } else {
            if (o.size() == 6) { // quadratic face: four flat triangles through its edge nodes,
                // so the surface follows the edge nodes and loads reach all six
                for (const auto& t : {std::array<std::int32_t, 3>{o[0], o[3], o[5]},
                                      std::array<std::int32_t, 3>{o[3], o[1], o[4]},
                                      std::array<std::int32_t, 3>{o[5], o[4], o[2]},
                                      std::array<std::int32_t, 3>{o[3], o[4], o[5]}}) {
                    f.nodes = t;
                    out.push_back(f);
                }
                continue;
            }
            f.nodes = {o[0], o[1], o[2]};
            out.push_back(f);
            if (o.size() == 4) {
                f.nodes = {o[0], o[2], o[3]};
                out.push_back(f);
            }
        }
    }
    return out;
}

Vec3 facet_normal(const SurfaceFacet& f, const std::vector<Vec3>& x) {
    const Vec3 a = x[std::size_t(f.nodes[0])], b = x[std::size_t(f.nodes[1])];
    Vec3 n;
    if (f.nodes[2] < 0) {
        const Vec3 d = b - a;
        n = {d.z, 0, -d.x};
    } else {
        n = cross(b - a, x[std::size_t(f.nodes[2])] - a);
    }
    const Real l = norm(n);
    return l > 0 ? (1 / l) * n : n;
}

Real facet_distance(const SurfaceFacet& f, const std::vector<Vec3>& x, Vec3 p) {
    const Vec3 a = x[std::size_t(f.nodes[0])], b = x[std::size_t(f.nodes[1])];
    Vec3 q;
    if (f.nodes[2] < 0) {
        const Vec3 d = b - a;
        const Real s = std::clamp(dot(p - a, d) / dot(d, d), Real(0), Real(1));
        q = a + s * d;
    } else {
        q = dem::closest_on_triangle(p, a, b, x[std::size_t(f.nodes[2])]);
    }
    return norm(p - q);
}

std::vector<Real> shape_values(ElementType t, const std::array<Real, 3>& xi) {
    switch (t) {
    case ElementType::hex8: {
        static const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
        std::vector<Real> n(8);
        for (int a = 0; a < 8; ++a)
            n[std::size_t(a)] =
                (1 + s[a][0] * xi[0]) * (1 + s[a][1] * xi[1]) * (1 + s[a][2] * xi[2]) / 8;
        return n;
    }
    case ElementType::quad4: {
        static const int s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        std::vector<Real> n(4);
        for (int a = 0; a < 4; ++a)
            n[std::size_t(a)] = (1 + s[a][0] * xi[0]) * (1 + s[a][1] * xi[1]) / 4;
        return n;
    }
    case ElementType::tet4:
        return {1 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
    case ElementType::tet10: {
        const Real L[4] = {1 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
        static const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
        std::vector<Real> n(10);
        for (int a = 0; a < 4; ++a) n[std::size_t(a)] = L[a] * (2 * L[a] - 1);
        for (int e = 0; e < 6; ++e) n[std::size_t(4 + e)] = 4 * L[edges[e][0]] * L[edges[e][1]];
        return n;
    }
    }
    return {};
}

bool locate(const FemSolver& fem, std::size_t s, std::size_t e, Vec3 p, std::array<Real, 3>& xi) {
    const auto& so = fem.solids()[s];
    const int nn = nodes_of(so.type);
    const std::int32_t* c = &so.conn[e * std::size_t(nn)];
    const auto& X = fem.reference();
    constexpr Real tol = 1e-9;
    if (so.type == ElementType::tet4 || so.type == ElementType::tet10) {
        const Vec3 a = X[std::size_t(c[0])];
        Eigen::Matrix3d J;
        for (int k = 0; k < 3; ++k)
            for (int r = 0; r < 3; ++r) J(r, k) = X[std::size_t(c[k + 1])][r] - a[r];
        const Eigen::Vector3d l =
            J.partialPivLu().solve(Eigen::Vector3d(p.x - a.x, p.y - a.y, p.z - a.z));
        xi = {l[0], l[1], l[2]};
        return l.minCoeff() >= -tol && l.sum() <= 1 + tol;
    }
    const bool flat = so.type == ElementType::quad4;
    const int dim = flat ? 2 : 3;
    xi = {0, 0, 0};
    for (int it = 0; it < 20; ++it) {
        const auto n = shape_values(so.type, xi);
        Vec3 x{};
        for (int a = 0; a < nn; ++a) x = x + n[std::size_t(a)] * X[std::size_t(c[a])];
        const Vec3 r = p - x;
        // Jacobian by central differences of the (multi)linear map: exact for it.
        Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
        for (int k = 0; k < dim; ++k) {
            auto xp = xi, xm = xi;
            xp[std::size_t(k)] += 0.5, xm[std::size_t(k)] -= 0.5;
            const auto np = shape_values(so.type, xp), nm = shape_values(so.type, xm);
            Vec3 d{};
            for (int a = 0; a < nn; ++a)
                d = d + (np[std::size_t(a)] - nm[std::size_t(a)]) * X[std::size_t(c[a])];
            if (flat) {
                J(0, k) = d.x, J(1, k) = d.z;
            } else {
                J(0, k) = d.x, J(1, k) = d.y, J(2, k) = d.z;
            }
        }
        const Eigen::Vector3d rhs =
            flat ? Eigen::Vector3d(r.x, r.z, 0) : Eigen::Vector3d(r.x, r.y, r.z);
        const Eigen::Vector3d dxi = J.partialPivLu().solve(rhs);
        for (int k = 0; k < dim; ++k) xi[std::size_t(k)] += dxi[k];
        if (dxi.norm() < 1e-12) break;
    }
    for (int k = 0; k < dim; ++k)
        if (std::fabs(xi[std::size_t(k)]) > 1 + tol) return false;
    return true;
}

} // namespace debrisflow::fem
