#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <Eigen/Dense>
#include <cmath>
#include <cstdint>

// The corotational kinematics of the FEM elements, shared by the force loop
// (fem/fem_solver.cpp) and the element results (fem/fem_results.cpp).
namespace debrisflow::fem {

using VecN = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 30, 1>;
using Vec6 = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 6, 1>;

// World component of local component k (2D solids live in the x-z plane).
inline int world_axis(int dim, int k) {
    return dim == 3 ? k : 2 * k;
}

// Rotation of the polar decomposition F = R U (dim x dim, in the leading block of a 3x3).
inline Eigen::Matrix3d polar_rotation(const Eigen::Matrix3d& F, int dim) {
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    if (dim == 2) {
        const Real th = std::atan2(F(1, 0) - F(0, 1), F(0, 0) + F(1, 1));
        R(0, 0) = R(1, 1) = std::cos(th);
        R(1, 0) = std::sin(th);
        R(0, 1) = -R(1, 0);
        return R;
    }
    // Newton's polar iteration R <- (R + R^-T) / 2 from F (Higham 1986): quadratic convergence,
    // a few 3x3 inverses; the SVD only for inverted elements.
    if (F.determinant() > 0) {
        Eigen::Matrix3d R = F;
        for (int it = 0; it < 30; ++it) {
            const Eigen::Matrix3d next = Real(0.5) * (R + R.inverse().transpose());
            const Real change = (next - R).cwiseAbs().maxCoeff();
            R = next;
            if (change < Real(1e-14)) break;
        }
        return R;
    }
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d U = svd.matrixU();
    const Eigen::Matrix3d V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0) U.col(2) *= -1;
    return U * V.transpose();
}

// Principal values of a Voigt strain (engineering shears) in dim dimensions (plane strain:
// the third is 0).
inline Eigen::Vector3d principal_strains(const Vec6& e, int dim) {
    if (dim == 2) {
        const Real c = (e[0] + e[1]) / 2, r = std::hypot((e[0] - e[1]) / 2, e[2] / 2);
        return {c + r, 0, c - r};
    }
    Eigen::Matrix3d t;
    t << e[0], e[3] / 2, e[5] / 2, e[3] / 2, e[1], e[4] / 2, e[5] / 2, e[4] / 2, e[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(t, Eigen::EigenvaluesOnly);
    return eig.eigenvalues().reverse();
}

// Corotational frame of an element (Felippa & Haugen 2005): the rotation R of the polar
// decomposition of F = sum (x_a - x_c) (x) g_a at the centre, the local displacements
// u = R^T (x_a - x_c) - (X_a - X_c) and, when w is given, the local velocities R^T v_a.
template <int DIM>
inline Eigen::Matrix3d corotate(int nn, const std::int32_t* c, const Real* g, const Vec3* X,
                                const Vec3* x, const Vec3* v, Real* u, Real* w) {
    Vec3 xc{}, Xc{};
    for (int a = 0; a < nn; ++a) {
        xc = xc + x[c[a]];
        Xc = Xc + X[c[a]];
    }
    xc = (Real(1) / nn) * xc;
    Xc = (Real(1) / nn) * Xc;
    Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
    for (int a = 0; a < nn; ++a) {
        const Vec3 d = x[c[a]] - xc;
        for (int i = 0; i < DIM; ++i)
            for (int j = 0; j < DIM; ++j)
                F(i, j) += d[world_axis(DIM, i)] * g[a + j * nn]; // g is nn x DIM
    }
    const Eigen::Matrix3d R = polar_rotation(F, DIM);
    for (int a = 0; a < nn; ++a) {
        const Vec3 d = x[c[a]] - xc, D = X[c[a]] - Xc;
        for (int i = 0; i < DIM; ++i) {
            Real rd = 0, rv = 0;
            for (int j = 0; j < DIM; ++j) {
                rd += R(j, i) * d[world_axis(DIM, j)];
                if (w) rv += R(j, i) * v[c[a]][world_axis(DIM, j)];
            }
            u[a * DIM + i] = rd - D[world_axis(DIM, i)];
            if (w) w[a * DIM + i] = rv;
        }
    }
    return R;
}

} // namespace debrisflow::fem
