#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/fem/element_type.hpp"
#include <Eigen/Dense>
#include <vector>

namespace debrisflow::fem {

// Isotropic linear elasticity in Voigt form: 3D (xx, yy, zz, xy, yz, zx; engineering shears)
// or plane strain in the x-z plane (xx, zz, xz).
Eigen::MatrixXd elasticity_matrix(Real youngs, Real poisson, int dim);

// What an element needs through the run, in its reference configuration (local dofs: node a,
// component k at a * dim + k; in 2D the components are x and z):
struct ElementMatrices {
    Eigen::MatrixXd stiffness; // condensed K (incompatible modes eliminated) [N/m]
    Eigen::MatrixXd strain;    // strain at the element centre = strain * u_e
    Eigen::MatrixXd gradient;  // dN_a/dX at the centre (nodes x dim), for F = sum x_a (x) g_a
    Eigen::VectorXd mass;      // lumped nodal masses [kg] (2D: per metre)
    Real volume = 0;           // [m^3] (2D: m^2)
    Real omega_max = 0;        // largest eigenfrequency of K u = w^2 M u on the element [rad/s]
};

// Element matrices of element type t with nodes X (world coordinates; 2D uses x and z),
// elasticity C and density rho. Stiffness by Gauss quadrature (hex8 2x2x2, quad4 2x2, tet4 1,
// tet10 4 points); hex8 and quad4 carry Wilson's incompatible modes with Taylor's centre-
// Jacobian correction (passes the patch test on distorted meshes), condensed statically.
// Masses: row sums for the linear elements, HRZ diagonal scaling for tet10 (Hinton, Rock &
// Zienkiewicz 1976). Throws InputError for an inverted element (det J <= 0).
ElementMatrices element_matrices(ElementType t, const std::vector<Vec3>& X,
                                 const Eigen::MatrixXd& C, Real rho);

} // namespace debrisflow::fem
