#pragma once
#include "debrisflow/fem/element_type.hpp"
#include "debrisflow/fem/fem_material.hpp"
#include "debrisflow/fem/fem_mesh.hpp"
#include "debrisflow/fem/fem_params.hpp"
#include "debrisflow/time/phase.hpp"
#include <Eigen/Dense>
#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::fem {

// A nodal load: `force` [N] (2D: N/m) shared equally by the nodes, scaled by a
// piecewise-linear table of time (constant 1 without one).
struct FemLoad {
    std::vector<std::int32_t> nodes; // global node indices
    Vec3 force;
    std::vector<Real> times, scale;
};

// Stress, strain and damage of one element at its centre (world frame; Voigt order xx, yy,
// zz, xy, yz, zx with tensor shears for the strain; in 2D yy is the plane-strain stress).
struct ElementResult {
    std::array<Real, 6> stress{}, strain{};
    Real von_mises = 0, max_principal_strain = 0, damage = 0;
    bool eroded = false;
};

// Explicit dynamics of solid meshes (section D's retaining dam): corotational small-strain
// elements (the element rotation R from the polar decomposition of F at its centre;
// f = -(1 - D) R K_e (R^T (x - x_c) - (X - X_c)), Felippa & Haugen 2005), lumped masses,
// central differences (kick-drift-kick) sub-cycled inside the global step, Rayleigh damping
// C = alpha M + beta K, Mazars damage and element erosion. Loads from the fluid and the grains
// arrive as external nodal forces between global steps.
class FemSolver : public time::Phase {
public:
    FemSolver(FemParams params, std::vector<FemMaterial> materials);

    // Adds a solid; returns its index. Node sets keep their names as "<solid>.<set>".
    int add_solid(const std::string& name, const FemMesh& mesh, int material);
    // Fixes the listed DOFs (x, y, z) of nodes.
    void fix(const std::vector<std::int32_t>& nodes, std::array<bool, 3> dofs);
    void add_load(FemLoad load);
    // Call after the solids, supports and loads are in: masses, element bound, accelerations.
    void initialize();

    const char* name() const override { return "fem"; }
    void update_neighbors(bool) override {}
    // Collects the coupling loads (load sources) into external_forces().
    void compute_forces() override;
    // Places the coupled surfaces half a step ahead (the fluid's mid-step state).
    void predictor(Real dt) override;
    void corrector(Real dt) override;
    void verlet_step(Real dt, bool) override;

    // Coupling: a load source adds nodal forces [N] at every force evaluation; a surface mover
    // places coupled particles from the nodes, `ahead` seconds extrapolated along the velocity.
    void add_load_source(std::function<void(std::vector<Vec3>&)> source);
    void add_surface_mover(std::function<void(Real ahead)> mover);
    // A step source adds, at the start of every advance(dt), the nodal forces [N] that are
    // held over that advance: impulses gathered during the step divided by dt (the grains),
    // so that exactly the impulse the grains received reaches the nodes.
    void add_step_source(std::function<void(std::vector<Vec3>& f, Real dt)> source);
    // Total load a coupling put on the solids at its last evaluation [N] ("fluid", "grains").
    void report_interface_force(const std::string& source, Vec3 f) { interface_[source] = f; }
    Vec3 interface_force(const std::string& source) const {
        const auto it = interface_.find(source);
        return it == interface_.end() ? Vec3{} : it->second;
    }
    time::DtLimit stable_dt() const override;
    void check_health(Real t) const override;
    void add_timings(time::Timings& t) const override;

    // Advances by dt in equal central-difference steps no larger than critical_dt().
    void advance(Real dt);
    // Critical step: cfl x 2 / w_max (sqrt(1 + xi^2) - xi), xi = beta w_max / 2, with w_max the
    // largest element eigenfrequency (an upper bound of the mesh's, Irons 1970).
    Real critical_dt() const { return critical_dt_; }
    Real time() const { return t_; }
    long substeps() const { return substeps_; }

    // Nodes (all solids, in order of addition).
    std::size_t nodes() const { return x_.size(); }
    const std::vector<Vec3>& reference() const { return X_; }
    const std::vector<Vec3>& positions() const { return x_; }
    const std::vector<Vec3>& velocities() const { return v_; }
    std::vector<Vec3>& velocities() { return v_; }
    std::vector<Vec3>& positions() { return x_; }
    const std::vector<Real>& masses() const { return mass_; }
    // External nodal forces (coupling), held over the next advance [N].
    std::vector<Vec3>& external_forces() { return f_ext_; }
    Vec3 displacement(std::size_t n) const { return x_[n] - X_[n]; }
    // Load of the couplings on node n over the last advance: fluid and bodies (load sources)
    // plus grains (step sources) [N].
    Vec3 coupling_force(std::size_t n) const {
        return f_ext_[n] + (f_step_.empty() ? Vec3{} : f_step_[n]);
    }
    // Node set by name "<solid>.<set>"; throws InputError when absent.
    const std::vector<std::int32_t>& node_set(const std::string& name) const;
    bool has_node_set(const std::string& name) const;

    struct Solid {
        std::string name;
        ElementType type;
        int material;
        std::int32_t first_node, nodes;
        std::vector<std::int32_t> conn; // global node ids
        // Element matrices are shared between elements of the same shape (structured meshes):
        // element e uses matrix set shape[e] of the pools below.
        std::vector<std::int32_t> shape;
        std::vector<Real> stiffness; // per shape ndof x ndof (column-major)
        std::vector<Real> strain_op; // per shape ns x ndof
        std::vector<Real> gradient;  // per shape nn x dim
        std::vector<Real> volume, kappa, damage;
        std::vector<std::uint8_t> eroded;
        std::vector<Real> force; // per element ndof (internal force on its nodes)
    };
    const std::vector<Solid>& solids() const { return solids_; }
    ElementResult element_result(std::size_t solid, std::size_t e) const;
    // Global stiffness (reference configuration) and lumped masses per DOF, dense: for patch
    // tests, static solutions and modal analysis of small meshes (DOF n * dim + k).
    Eigen::MatrixXd assemble_stiffness() const;
    Eigen::VectorXd dof_masses() const;
    long eroded_elements() const;
    // Saves or restores nodes, damage, erosion and the sub-cycle's state
    // (fem/fem_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    void internal_forces(bool update_damage);
    void accelerations();
    void step(Real h);

    FemParams params_;
    std::vector<FemMaterial> materials_;
    std::vector<Solid> solids_;
    std::vector<std::pair<std::string, std::vector<std::int32_t>>> sets_;
    std::vector<Vec3> X_, x_, v_, a_, f_int_, f_ext_;
    std::vector<Real> mass_;
    std::vector<std::uint8_t> fixed_; // bit k: DOF k fixed
    std::vector<FemLoad> loads_;
    std::vector<std::function<void(std::vector<Vec3>&)>> sources_;
    std::vector<std::function<void(Real)>> movers_;
    std::vector<std::function<void(std::vector<Vec3>&, Real)>> step_sources_;
    std::vector<Vec3> f_step_;
    std::map<std::string, Vec3> interface_;
    // node -> (solid, element, local node) incidences (CSR) for the force gather
    std::vector<std::int32_t> inc_start_;
    std::vector<std::array<std::int32_t, 3>> inc_;
    Real critical_dt_ = 0, t_ = 0;
    long substeps_ = 0;
    bool initialized_ = false;
    double t_forces_ = 0, t_integrate_ = 0;
};

} // namespace debrisflow::fem
