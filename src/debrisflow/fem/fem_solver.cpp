#include "debrisflow/fem/fem_solver.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/fem/corotation.hpp"
#include "debrisflow/fem/element_matrices.hpp"
#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>

namespace debrisflow::fem {

namespace {

Real interpolate(const std::vector<Real>& t, const std::vector<Real>& v, Real at) {
    if (t.empty()) return 1;
    if (at <= t.front()) return v.front();
    for (std::size_t k = 1; k < t.size(); ++k)
        if (at <= t[k]) return v[k - 1] + (v[k] - v[k - 1]) * (at - t[k - 1]) / (t[k] - t[k - 1]);
    return v.back();
}

} // namespace

FemSolver::FemSolver(FemParams params, std::vector<FemMaterial> materials)
    : params_(params), materials_(std::move(materials)) {}

int FemSolver::add_solid(const std::string& name, const FemMesh& mesh, int material) {
    if (dim_of(mesh.type) != params_.dim)
        throw InputError(fmt::format("solid '{}': {} elements in a {}D case", name,
                                     name_of(mesh.type), params_.dim));
    const FemMaterial& mat = materials_.at(std::size_t(material));
    const Eigen::MatrixXd C = elasticity_matrix(mat.youngs_modulus, mat.poisson, params_.dim);
    Solid s;
    s.name = name;
    s.type = mesh.type;
    s.material = material;
    s.first_node = std::int32_t(X_.size());
    s.nodes = std::int32_t(mesh.nodes.size());
    for (const Vec3& p : mesh.nodes) {
        X_.push_back(p);
        x_.push_back(p);
        mass_.push_back(0);
    }
    const int nn = nodes_of(mesh.type), dim = params_.dim, ndof = nn * dim;
    const std::size_t ne = mesh.elements();
    std::vector<Vec3> xe(static_cast<std::size_t>(nn));
    Real omega = 0;
    // Elements whose node offsets from their first node agree (to 1e-9 of the element size)
    // share one set of matrices: a structured mesh stores a handful.
    std::map<std::vector<long long>, std::int32_t> shapes;
    std::vector<Eigen::VectorXd> shape_mass;
    std::vector<Real> shape_volume;
    for (std::size_t e = 0; e < ne; ++e) {
        for (int a = 0; a < nn; ++a) {
            const std::int32_t n = mesh.conn[e * std::size_t(nn) + std::size_t(a)];
            xe[std::size_t(a)] = mesh.nodes[std::size_t(n)];
            s.conn.push_back(s.first_node + n);
        }
        Real size = 0;
        for (int a = 1; a < nn; ++a) size = std::max(size, norm(xe[std::size_t(a)] - xe[0]));
        std::vector<long long> key;
        for (int a = 1; a < nn; ++a)
            for (int k = 0; k < 3; ++k)
                key.push_back(std::llround((xe[std::size_t(a)][k] - xe[0][k]) / (1e-9 * size)));
        key.push_back(std::llround(std::log2(size) * 1e6));
        const auto found = shapes.find(key);
        if (found != shapes.end()) {
            s.shape.push_back(found->second);
        } else {
            ElementMatrices m;
            try {
                m = element_matrices(mesh.type, xe, C, mat.density);
            } catch (const InputError& err) {
                throw InputError(fmt::format("solid '{}', element {}: {}", name, e, err.what()));
            }
            const std::int32_t id = std::int32_t(shapes.size());
            shapes.emplace(key, id);
            s.shape.push_back(id);
            shape_mass.push_back(m.mass);
            shape_volume.push_back(m.volume);
            omega = std::max(omega, m.omega_max);
            s.stiffness.insert(s.stiffness.end(), m.stiffness.data(),
                               m.stiffness.data() + ndof * ndof);
            s.strain_op.insert(s.strain_op.end(), m.strain.data(),
                               m.strain.data() + m.strain.size());
            s.gradient.insert(s.gradient.end(), m.gradient.data(),
                              m.gradient.data() + m.gradient.size());
        }
        const std::size_t k = std::size_t(s.shape.back());
        s.volume.push_back(shape_volume[k]);
        for (int a = 0; a < nn; ++a)
            mass_[std::size_t(s.conn[e * std::size_t(nn) + std::size_t(a)])] += shape_mass[k][a];
    }
    s.kappa.assign(ne, mat.damage_threshold);
    s.damage.assign(ne, 0);
    s.eroded.assign(ne, 0);
    s.force.assign(ne * std::size_t(ndof), 0);
    for (const auto& [set, nodes] : mesh.node_sets) {
        std::vector<std::int32_t> global;
        for (auto n : nodes) global.push_back(s.first_node + n);
        sets_.push_back({name + "." + set, std::move(global)});
    }
    std::vector<std::int32_t> all(std::size_t(s.nodes));
    for (std::int32_t n = 0; n < s.nodes; ++n) all[std::size_t(n)] = s.first_node + n;
    sets_.push_back({name, std::move(all)});
    solids_.push_back(std::move(s));
    const Real xi = params_.beta * omega / 2;
    const Real dt = params_.cfl * 2 / omega * (std::sqrt(1 + xi * xi) - xi);
    critical_dt_ = critical_dt_ > 0 ? std::min(critical_dt_, dt) : dt;
    initialized_ = false;
    return int(solids_.size()) - 1;
}

void FemSolver::fix(const std::vector<std::int32_t>& nodes, std::array<bool, 3> dofs) {
    fixed_.resize(X_.size(), 0);
    for (auto n : nodes)
        for (int k = 0; k < 3; ++k)
            if (dofs[std::size_t(k)]) fixed_[std::size_t(n)] |= std::uint8_t(1u << k);
}

void FemSolver::add_load(FemLoad load) {
    loads_.push_back(std::move(load));
}

bool FemSolver::has_node_set(const std::string& name) const {
    for (const auto& s : sets_)
        if (s.first == name) return true;
    return false;
}

const std::vector<std::int32_t>& FemSolver::node_set(const std::string& name) const {
    for (const auto& s : sets_)
        if (s.first == name) return s.second;
    std::string known;
    for (const auto& s : sets_) known += (known.empty() ? "" : ", ") + s.first;
    throw InputError(fmt::format("no FEM node set '{}' (known: {})", name, known));
}

void FemSolver::initialize() {
    const std::size_t n = X_.size();
    fixed_.resize(n, 0);
    v_.resize(n);
    a_.assign(n, {});
    f_int_.assign(n, {});
    f_ext_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        if (!(mass_[i] > 0)) throw InputError(fmt::format("FEM node {} carries no mass", i));
    // Node -> element incidences.
    std::vector<std::int32_t> count(n + 1, 0);
    for (const auto& s : solids_)
        for (auto c : s.conn) ++count[std::size_t(c) + 1];
    for (std::size_t i = 0; i < n; ++i) count[i + 1] += count[i];
    inc_start_ = count;
    inc_.assign(std::size_t(count[n]), {});
    std::vector<std::int32_t> fill(count.begin(), count.end() - 1);
    for (std::size_t si = 0; si < solids_.size(); ++si) {
        const auto& s = solids_[si];
        const int nn = nodes_of(s.type);
        for (std::size_t k = 0; k < s.conn.size(); ++k)
            inc_[std::size_t(fill[std::size_t(s.conn[k])]++)] = {std::int32_t(si),
                                                                 std::int32_t(k / std::size_t(nn)),
                                                                 std::int32_t(k % std::size_t(nn))};
    }
    internal_forces(false);
    accelerations();
    initialized_ = true;
}

namespace {

// Corotational force of element e of a solid with NN nodes in DIM dimensions (fixed sizes so
// that K_e u is an unrolled small product): f = -(1 - D) R K_e (R^T (x - x_c) - (X - X_c)),
// plus the stiffness-proportional damping beta K_e R^T v; updates damage and erosion.
template <int NN, int DIM>
void element_force(FemSolver::Solid& so, const FemMaterial& mat, const Vec3* X, const Vec3* x,
                   const Vec3* v, Real beta, bool update_damage, Index e) {
    constexpr int ndof = NN * DIM, ns = DIM == 3 ? 6 : 3;
    using VecD = Eigen::Matrix<Real, ndof, 1>;
    Real* out = &so.force[std::size_t(e) * std::size_t(ndof)];
    if (so.eroded[std::size_t(e)]) {
        for (int k = 0; k < ndof; ++k) out[k] = 0;
        return;
    }
    const std::int32_t* c = &so.conn[std::size_t(e) * std::size_t(NN)];
    const std::size_t k = std::size_t(so.shape[std::size_t(e)]);
    VecD u, w;
    const Eigen::Matrix3d R =
        corotate<DIM>(NN, c, &so.gradient[k * std::size_t(NN * DIM)], X, x, v, u.data(), w.data());
    const Eigen::Map<const Eigen::Matrix<Real, ndof, ndof>> K(
        &so.stiffness[k * std::size_t(ndof * ndof)]);
    if (update_damage && (mat.damages() || mat.erosion_strain > 0)) {
        const Eigen::Map<const Eigen::Matrix<Real, ns, ndof>> S(
            &so.strain_op[k * std::size_t(ns * ndof)]);
        const Vec6 eps = S * u;
        const Eigen::Vector3d pr = principal_strains(eps, DIM);
        if (mat.damages()) {
            const Real p[3] = {pr[0], pr[1], pr[2]};
            Real& kappa = so.kappa[std::size_t(e)];
            kappa = std::max(kappa, mazars_equivalent_strain(p));
            so.damage[std::size_t(e)] = mazars_damage(mat, kappa);
        }
        if (mat.erosion_strain > 0 && pr[0] > mat.erosion_strain) {
            so.eroded[std::size_t(e)] = 1;
            for (int k = 0; k < ndof; ++k) out[k] = 0;
            return;
        }
    }
    VecD f = K * u;
    if (beta > 0) f += beta * (K * w);
    const Real scale = 1 - so.damage[std::size_t(e)];
    for (int a = 0; a < NN; ++a)
        for (int i = 0; i < DIM; ++i) {
            Real r = 0;
            for (int j = 0; j < DIM; ++j) r += R(i, j) * f[a * DIM + j];
            out[a * DIM + i] = -scale * r;
        }
}

template <int NN, int DIM>
void solid_forces(FemSolver::Solid& s, const FemMaterial& mat, const Vec3* X, const Vec3* x,
                  const Vec3* v, Real beta, bool update_damage) {
    FemSolver::Solid* sp = &s;
    const FemMaterial* mp = &mat;
    exec::for_each(Index(s.volume.size()), [=](Index e) {
        element_force<NN, DIM>(*sp, *mp, X, x, v, beta, update_damage, e);
    });
}

} // namespace

void FemSolver::internal_forces(bool update_damage) {
    ScopedTimer timer(t_forces_);
    const int dim = params_.dim;
    const Real beta = params_.beta;
    for (auto& s : solids_) {
        const FemMaterial& mat = materials_[std::size_t(s.material)];
        const Vec3 *X = X_.data(), *x = x_.data(), *v = v_.data();
        switch (s.type) {
        case ElementType::hex8:
            solid_forces<8, 3>(s, mat, X, x, v, beta, update_damage);
            break;
        case ElementType::tet4:
            solid_forces<4, 3>(s, mat, X, x, v, beta, update_damage);
            break;
        case ElementType::tet10:
            solid_forces<10, 3>(s, mat, X, x, v, beta, update_damage);
            break;
        case ElementType::quad4:
            solid_forces<4, 2>(s, mat, X, x, v, beta, update_damage);
            break;
        }
    }
    const std::int32_t* start = inc_start_.data();
    const auto* inc = inc_.data();
    const Solid* solids = solids_.data();
    Vec3* fi = f_int_.data();
    exec::for_each(Index(X_.size()), [=](Index n) {
        Vec3 f{};
        for (std::int32_t k = start[n]; k < start[n + 1]; ++k) {
            const auto& [si, e, a] = inc[k];
            const Solid& s = solids[si];
            const int ndof = nodes_of(s.type) * dim;
            const Real* fe = &s.force[std::size_t(e) * std::size_t(ndof) + std::size_t(a * dim)];
            for (int i = 0; i < dim; ++i) f[world_axis(dim, i)] += fe[i];
        }
        fi[n] = f;
    });
}

void FemSolver::accelerations() {
    const std::size_t n = X_.size();
    std::vector<Vec3> load(n);
    for (const auto& l : loads_) {
        const Real s = interpolate(l.times, l.scale, t_) / Real(l.nodes.size());
        for (auto i : l.nodes) load[std::size_t(i)] = load[std::size_t(i)] + s * l.force;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 f_step = f_step_.empty() ? Vec3{} : f_step_[i];
        Vec3 a = (1 / mass_[i]) * (f_int_[i] + f_ext_[i] + f_step + load[i]) + params_.gravity -
                 params_.alpha * v_[i];
        if (params_.dim == 2) a.y = 0;
        for (int k = 0; k < 3; ++k)
            if (fixed_[i] & (1u << k)) a[k] = 0;
        a_[i] = a;
    }
}

void FemSolver::step(Real h) {
    const std::size_t n = X_.size();
    {
        ScopedTimer timer(t_integrate_);
        for (std::size_t i = 0; i < n; ++i) {
            v_[i] = v_[i] + (h / 2) * a_[i];
            for (int k = 0; k < 3; ++k)
                if (fixed_[i] & (1u << k)) v_[i][k] = 0;
            x_[i] = x_[i] + h * v_[i];
        }
    }
    t_ += h;
    internal_forces(true);
    accelerations();
    for (std::size_t i = 0; i < n; ++i) v_[i] = v_[i] + (h / 2) * a_[i];
    ++substeps_;
}

void FemSolver::add_load_source(std::function<void(std::vector<Vec3>&)> source) {
    sources_.push_back(std::move(source));
}

void FemSolver::add_surface_mover(std::function<void(Real)> mover) {
    movers_.push_back(std::move(mover));
}

void FemSolver::add_step_source(std::function<void(std::vector<Vec3>&, Real)> source) {
    step_sources_.push_back(std::move(source));
}

void FemSolver::compute_forces() {
    if (sources_.empty()) return;
    if (!initialized_) initialize();
    std::fill(f_ext_.begin(), f_ext_.end(), Vec3{});
    for (auto& s : sources_) s(f_ext_);
}

void FemSolver::predictor(Real dt) {
    for (auto& m : movers_) m(dt / 2);
}

void FemSolver::corrector(Real dt) {
    advance(dt);
    for (auto& m : movers_) m(0);
}

void FemSolver::verlet_step(Real dt, bool) {
    advance(dt);
    for (auto& m : movers_) m(0);
}

void FemSolver::advance(Real dt) {
    if (!initialized_) initialize();
    f_step_.assign(x_.size(), Vec3{});
    for (auto& s : step_sources_) s(f_step_, dt);
    accelerations(); // external loads may have changed since the last step
    const long n = std::max(1L, long(std::ceil(dt / critical_dt_ - 1e-9)));
    const Real h = dt / Real(n);
    for (long k = 0; k < n; ++k) step(h);
}

time::DtLimit FemSolver::stable_dt() const {
    if (params_.max_subcycles > 0) return {critical_dt_ * params_.max_subcycles, "fem element CFL"};
    return {std::numeric_limits<Real>::max(), "fem (sub-cycled)"};
}

void FemSolver::check_health(Real t) const {
    for (std::size_t i = 0; i < x_.size(); ++i) {
        const Vec3 p = x_[i];
        bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        bool inside = true;
        for (int k = 0; k < 3; ++k)
            if (!(params_.dim == 2 && k == 1))
                inside = inside && p[k] >= params_.domain_min[k] && p[k] <= params_.domain_max[k];
        if (!finite || !inside)
            throw InstabilityError(fmt::format(
                "FEM node {} {} at t = {:.6g} s: position ({:.4g}, {:.4g}, {:.4g}) m, velocity "
                "({:.4g}, {:.4g}, {:.4g}) m/s (FEM step {:.3g} s)",
                i, finite ? "left the domain" : "is not finite", t, p.x, p.y, p.z, v_[i].x, v_[i].y,
                v_[i].z, critical_dt_));
    }
}

void FemSolver::add_timings(time::Timings& t) const {
    t.forces += t_forces_;
    t.integration += t_integrate_;
}

} // namespace debrisflow::fem
