#include "debrisflow/fem/element_matrices.hpp"
#include "debrisflow/core/error.hpp"
#include <array>
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::fem {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct QuadPoint {
    Eigen::Vector3d xi;
    Real w;
};

// Shape functions and their natural derivatives (nodes x dim) at xi.
struct Shape {
    VectorXd n;
    MatrixXd dn;
};

constexpr int hex_sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr int quad_sign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
// tet10 edge nodes 4..9 (VTK order): the corners they join.
constexpr int tet10_edge[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};

Shape shape(ElementType t, const Eigen::Vector3d& x) {
    Shape s;
    switch (t) {
    case ElementType::hex8:
        s.n.resize(8);
        s.dn.resize(8, 3);
        for (int a = 0; a < 8; ++a) {
            const Real f[3] = {1 + hex_sign[a][0] * x[0], 1 + hex_sign[a][1] * x[1],
                               1 + hex_sign[a][2] * x[2]};
            s.n[a] = f[0] * f[1] * f[2] / 8;
            s.dn(a, 0) = hex_sign[a][0] * f[1] * f[2] / 8;
            s.dn(a, 1) = hex_sign[a][1] * f[0] * f[2] / 8;
            s.dn(a, 2) = hex_sign[a][2] * f[0] * f[1] / 8;
        }
        break;
    case ElementType::quad4:
        s.n.resize(4);
        s.dn.resize(4, 2);
        for (int a = 0; a < 4; ++a) {
            const Real f[2] = {1 + quad_sign[a][0] * x[0], 1 + quad_sign[a][1] * x[1]};
            s.n[a] = f[0] * f[1] / 4;
            s.dn(a, 0) = quad_sign[a][0] * f[1] / 4;
            s.dn(a, 1) = quad_sign[a][1] * f[0] / 4;
        }
        break;
    case ElementType::tet4:
    case ElementType::tet10: {
        const Real L[4] = {1 - x[0] - x[1] - x[2], x[0], x[1], x[2]};
        const Eigen::Vector3d dL[4] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        const int n = t == ElementType::tet4 ? 4 : 10;
        s.n.resize(n);
        s.dn.resize(n, 3);
        if (t == ElementType::tet4) {
            for (int a = 0; a < 4; ++a) {
                s.n[a] = L[a];
                s.dn.row(a) = dL[a].transpose();
            }
        } else {
            for (int a = 0; a < 4; ++a) {
                s.n[a] = L[a] * (2 * L[a] - 1);
                s.dn.row(a) = ((4 * L[a] - 1) * dL[a]).transpose();
            }
            for (int e = 0; e < 6; ++e) {
                const int i = tet10_edge[e][0], j = tet10_edge[e][1];
                s.n[4 + e] = 4 * L[i] * L[j];
                s.dn.row(4 + e) = (4 * (L[i] * dL[j] + L[j] * dL[i])).transpose();
            }
        }
        break;
    }
    }
    return s;
}

std::vector<QuadPoint> gauss_rule(ElementType t) {
    std::vector<QuadPoint> q;
    const Real g = 1 / std::sqrt(Real(3));
    switch (t) {
    case ElementType::hex8:
        for (int a = 0; a < 8; ++a)
            q.push_back({{g * hex_sign[a][0], g * hex_sign[a][1], g * hex_sign[a][2]}, 1});
        break;
    case ElementType::quad4:
        for (int a = 0; a < 4; ++a) q.push_back({{g * quad_sign[a][0], g * quad_sign[a][1], 0}, 1});
        break;
    case ElementType::tet4:
        q.push_back({{0.25, 0.25, 0.25}, Real(1) / 6});
        break;
    case ElementType::tet10: {
        const Real a = 0.5854101966249685, b = 0.1381966011250105;
        for (const Eigen::Vector3d& x : {Eigen::Vector3d{b, b, b}, Eigen::Vector3d{a, b, b},
                                         Eigen::Vector3d{b, a, b}, Eigen::Vector3d{b, b, a}})
            q.push_back({x, Real(1) / 24});
        break;
    }
    }
    return q;
}

// Collapsed-cube Gauss rule on the unit tetrahedron (4^3 points, exact to degree 5 at least):
// for the tet10 consistent-mass diagonal.
std::vector<QuadPoint> tet_rule_fine() {
    const Real x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                       0.8611363115940526};
    const Real w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                       0.3478548451374538};
    std::vector<QuadPoint> q;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                const Real u = (x[i] + 1) / 2, v = (x[j] + 1) / 2, s = (x[k] + 1) / 2;
                const Eigen::Vector3d p{u, v * (1 - u), s * (1 - u) * (1 - v)};
                q.push_back({p, w[i] * w[j] * w[k] / 8 * (1 - u) * (1 - u) * (1 - v)});
            }
    return q;
}

Eigen::Vector3d centre(ElementType t) {
    return t == ElementType::tet4 || t == ElementType::tet10 ? Eigen::Vector3d{0.25, 0.25, 0.25}
                                                             : Eigen::Vector3d{0, 0, 0};
}

// Strain-displacement rows for one node with physical gradient g (dim entries).
void put_b(MatrixXd& B, int col, const Eigen::VectorXd& g, int dim) {
    if (dim == 3) {
        B(0, col) = g[0];
        B(1, col + 1) = g[1];
        B(2, col + 2) = g[2];
        B(3, col) = g[1], B(3, col + 1) = g[0];
        B(4, col + 1) = g[2], B(4, col + 2) = g[1];
        B(5, col) = g[2], B(5, col + 2) = g[0];
    } else {
        B(0, col) = g[0];
        B(1, col + 1) = g[1];
        B(2, col) = g[1], B(2, col + 1) = g[0];
    }
}

} // namespace

Eigen::MatrixXd elasticity_matrix(Real E, Real nu, int dim) {
    const Real lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    if (dim == 2) {
        MatrixXd C = MatrixXd::Zero(3, 3);
        C(0, 0) = C(1, 1) = lambda + 2 * mu;
        C(0, 1) = C(1, 0) = lambda;
        C(2, 2) = mu;
        return C;
    }
    MatrixXd C = MatrixXd::Zero(6, 6);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) C(i, j) = lambda;
        C(i, i) = lambda + 2 * mu;
        C(i + 3, i + 3) = mu;
    }
    return C;
}

ElementMatrices element_matrices(ElementType t, const std::vector<Vec3>& X,
                                 const Eigen::MatrixXd& C, Real rho) {
    const int dim = dim_of(t), nn = nodes_of(t), ndof = nn * dim;
    const int ns = dim == 3 ? 6 : 3;
    const bool incompatible = t == ElementType::hex8 || t == ElementType::quad4;
    const int ninc = incompatible ? dim * dim : 0;
    MatrixXd coords(nn, dim); // reference coordinates (2D: x, z)
    for (int a = 0; a < nn; ++a) {
        if (dim == 3)
            coords.row(a) << X[std::size_t(a)].x, X[std::size_t(a)].y, X[std::size_t(a)].z;
        else
            coords.row(a) << X[std::size_t(a)].x, X[std::size_t(a)].z;
    }
    auto jacobian = [&](const Shape& s) -> MatrixXd { return s.dn.transpose() * coords; };
    // J(i, j) = dX_j / dxi_i; physical gradients: J^-1 dN/dxi.
    const Shape s0 = shape(t, centre(t));
    const MatrixXd J0 = jacobian(s0);
    const Real det0 = J0.determinant();
    ElementMatrices out;
    MatrixXd K = MatrixXd::Zero(ndof + ninc, ndof + ninc);
    out.mass = VectorXd::Zero(nn);
    for (const auto& q : gauss_rule(t)) {
        const Shape s = shape(t, q.xi);
        const MatrixXd J = jacobian(s);
        const Real det = J.determinant();
        if (!(det > 0))
            throw InputError(fmt::format("{} element is inverted or degenerate (det J = {:.3g}); "
                                         "check the node order",
                                         name_of(t), det));
        const MatrixXd g = (J.inverse() * s.dn.transpose()).transpose(); // nodes x dim
        MatrixXd B = MatrixXd::Zero(ns, ndof + ninc);
        for (int a = 0; a < nn; ++a) put_b(B, a * dim, g.row(a).transpose(), dim);
        if (incompatible)
            for (int k = 0; k < dim; ++k) {
                // P_k = 1 - xi_k^2: dP/dxi = -2 xi_k e_k, mapped with J0 and scaled det0/det.
                Eigen::VectorXd dxi = Eigen::VectorXd::Zero(dim);
                dxi[k] = -2 * q.xi[k];
                const Eigen::VectorXd gp = (det0 / det) * (J0.inverse() * dxi);
                put_b(B, ndof + k * dim, gp, dim);
            }
        const Real dv = det * q.w;
        K += B.transpose() * C * B * dv;
        out.volume += dv;
        if (t != ElementType::tet10) out.mass += rho * dv * s.n;
    }
    if (incompatible) {
        const MatrixXd kaa = K.bottomRightCorner(ninc, ninc);
        const MatrixXd kau = K.bottomLeftCorner(ninc, ndof);
        out.stiffness = K.topLeftCorner(ndof, ndof) - kau.transpose() * kaa.ldlt().solve(kau);
    } else {
        out.stiffness = K;
    }
    out.stiffness = (out.stiffness + out.stiffness.transpose()) / 2;
    if (t == ElementType::tet10) { // HRZ: the consistent diagonal scaled to the total mass
        VectorXd diag = VectorXd::Zero(nn);
        for (const auto& q : tet_rule_fine()) {
            const Shape s = shape(t, q.xi);
            const Real det = jacobian(s).determinant();
            diag += (q.w * det) * s.n.cwiseProduct(s.n);
        }
        out.mass = (rho * out.volume / diag.sum()) * diag;
    }
    const MatrixXd g0 = (J0.inverse() * s0.dn.transpose()).transpose();
    out.gradient = g0;
    out.strain = MatrixXd::Zero(ns, ndof);
    for (int a = 0; a < nn; ++a) put_b(out.strain, a * dim, g0.row(a).transpose(), dim);
    // Largest element eigenfrequency: M^-1/2 K M^-1/2 (bounds the mesh's, Irons 1970).
    VectorXd m_dof(ndof);
    for (int a = 0; a < nn; ++a)
        for (int k = 0; k < dim; ++k) m_dof[a * dim + k] = 1 / std::sqrt(out.mass[a]);
    const MatrixXd A = m_dof.asDiagonal() * out.stiffness * m_dof.asDiagonal();
    Eigen::SelfAdjointEigenSolver<MatrixXd> eig(A, Eigen::EigenvaluesOnly);
    out.omega_max = std::sqrt(std::max(Real(0), eig.eigenvalues().maxCoeff()));
    return out;
}

} // namespace debrisflow::fem
