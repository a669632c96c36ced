// What the FEM solver reports of its elements and nodes: strain, stress and damage of one
// element in world axes, the assembled stiffness and the lumped masses (modal checks), the
// number of eroded elements.
#include "debrisflow/fem/corotation.hpp"
#include "debrisflow/fem/element_matrices.hpp"
#include "debrisflow/fem/fem_solver.hpp"

namespace debrisflow::fem {

ElementResult FemSolver::element_result(std::size_t si, std::size_t e) const {
    const Solid& s = solids_[si];
    const int dim = params_.dim, nn = nodes_of(s.type), ndof = nn * dim, ns = dim == 3 ? 6 : 3;
    const FemMaterial& mat = materials_[std::size_t(s.material)];
    ElementResult r;
    r.damage = s.damage[e];
    r.eroded = s.eroded[e] != 0;
    const std::int32_t* c = &s.conn[e * std::size_t(nn)];
    const std::size_t k = std::size_t(s.shape[e]);
    const Real* g = &s.gradient[k * std::size_t(nn * dim)];
    VecN u(ndof);
    const Eigen::Matrix3d R =
        dim == 3 ? corotate<3>(nn, c, g, X_.data(), x_.data(), nullptr, u.data(), nullptr)
                 : corotate<2>(nn, c, g, X_.data(), x_.data(), nullptr, u.data(), nullptr);
    const Eigen::Map<const Eigen::MatrixXd> S(&s.strain_op[k * std::size_t(ns * ndof)], ns, ndof);
    const Vec6 eps = S * u;
    const Eigen::MatrixXd C = elasticity_matrix(mat.youngs_modulus, mat.poisson, dim);
    const Vec6 sig = (1 - r.damage) * (C * eps);
    // Local tensors (3x3, world axes x, y, z) rotated back: T = R t R^T.
    Eigen::Matrix3d te = Eigen::Matrix3d::Zero(), ts = Eigen::Matrix3d::Zero();
    if (dim == 3) {
        te << eps[0], eps[3] / 2, eps[5] / 2, eps[3] / 2, eps[1], eps[4] / 2, eps[5] / 2,
            eps[4] / 2, eps[2];
        ts << sig[0], sig[3], sig[5], sig[3], sig[1], sig[4], sig[5], sig[4], sig[2];
        te = R * te * R.transpose();
        ts = R * ts * R.transpose();
    } else { // local (x, z) block; y is the plane-strain direction
        Eigen::Matrix2d e2, s2, R2 = R.topLeftCorner<2, 2>();
        e2 << eps[0], eps[2] / 2, eps[2] / 2, eps[1];
        s2 << sig[0], sig[2], sig[2], sig[1];
        e2 = R2 * e2 * R2.transpose();
        s2 = R2 * s2 * R2.transpose();
        te(0, 0) = e2(0, 0), te(2, 2) = e2(1, 1), te(0, 2) = te(2, 0) = e2(0, 1);
        ts(0, 0) = s2(0, 0), ts(2, 2) = s2(1, 1), ts(0, 2) = ts(2, 0) = s2(0, 1);
        ts(1, 1) = mat.poisson * (sig[0] + sig[1]); // plane strain
    }
    r.strain = {te(0, 0), te(1, 1), te(2, 2), te(0, 1), te(1, 2), te(0, 2)};
    r.stress = {ts(0, 0), ts(1, 1), ts(2, 2), ts(0, 1), ts(1, 2), ts(0, 2)};
    const Real sxx = ts(0, 0), syy = ts(1, 1), szz = ts(2, 2);
    r.von_mises = std::sqrt(Real(0.5) * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) +
                                         (szz - sxx) * (szz - sxx)) +
                            3 * (ts(0, 1) * ts(0, 1) + ts(1, 2) * ts(1, 2) + ts(0, 2) * ts(0, 2)));
    r.max_principal_strain = principal_strains(eps, dim)[0];
    return r;
}

Eigen::MatrixXd FemSolver::assemble_stiffness() const {
    const int dim = params_.dim;
    const Eigen::Index n = Eigen::Index(X_.size()) * dim;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (const auto& s : solids_) {
        const int nn = nodes_of(s.type), ndof = nn * dim;
        for (std::size_t e = 0; e < s.volume.size(); ++e) {
            if (s.eroded[e]) continue;
            const Eigen::Map<const Eigen::MatrixXd> ke(
                &s.stiffness[std::size_t(s.shape[e]) * std::size_t(ndof * ndof)], ndof, ndof);
            const std::int32_t* c = &s.conn[e * std::size_t(nn)];
            for (int a = 0; a < nn; ++a)
                for (int b = 0; b < nn; ++b)
                    K.block(c[a] * dim, c[b] * dim, dim, dim) +=
                        (1 - s.damage[e]) * ke.block(a * dim, b * dim, dim, dim);
        }
    }
    return K;
}

Eigen::VectorXd FemSolver::dof_masses() const {
    const int dim = params_.dim;
    Eigen::VectorXd m(Eigen::Index(X_.size()) * dim);
    for (std::size_t i = 0; i < X_.size(); ++i)
        for (int k = 0; k < dim; ++k) m[Eigen::Index(i) * dim + k] = mass_[i];
    return m;
}

long FemSolver::eroded_elements() const {
    long n = 0;
    for (const auto& s : solids_)
        for (auto e : s.eroded) n += e;
    return n;
}

} // namespace debrisflow::fem
