// Compiles the host/device SPH and DEM functors with nvcc and launches them from a CUDA
// kernel, so that every per-pair rule stays device-callable. No GPU is needed to compile this
// file.
#include "debrisflow/coupling/drag_laws_k.hpp"
#include "debrisflow/dem/grain_contact_k.hpp"
#include "debrisflow/kernels/cubic_spline_k.hpp"
#include "debrisflow/kernels/wendland_c2_k.hpp"
#include "debrisflow/models/density_diffusion_k.hpp"
#include "debrisflow/models/viscosity_k.hpp"
#include "debrisflow/rigid/body_state.hpp"
#include "debrisflow/sph/interaction_k.hpp"
#include "debrisflow/sph/viscosity_registry.hpp"

namespace debrisflow::cuda {

template <class F> __global__ void for_each_kernel(Index n, F f) {
    const Index i = Index(blockIdx.x) * Index(blockDim.x) + Index(threadIdx.x);
    if (i < n) f(i);
}

template <class F> void launch(Index n, const F& f) {
    const int block = 128;
    for_each_kernel<<<(n + block - 1) / block, block>>>(n, f);
}

template <class K, class V, class D> void instantiate_interaction() {
    launch(0, sph::FluidInteraction<K, V, D>{});
}

// Every viscosity model of the registry (with Fourtakas diffusion), and every diffusion model
// (with artificial viscosity): a model added to sph/viscosity_registry.hpp is compiled for the
// device here without another line.
template <class K, class... V> void instantiate_viscosities(models::Registry<V...>*) {
    (instantiate_interaction<K, V, models::Fourtakas>(), ...);
}

template <class K> void instantiate_kernel() {
    instantiate_viscosities<K>(static_cast<sph::ViscosityRegistry*>(nullptr));
    instantiate_interaction<K, models::ArtificialViscosity, models::NoDiffusion>();
    instantiate_interaction<K, models::ArtificialViscosity, models::MolteniColagrossi>();
}

// Every grain's contacts with its candidate partners and wall primitives, as a per-grain
// gather (each thread owns grain i; j's reaction is left to j's own thread in a full list).
struct DemContacts {
    dem::GrainView g;
    dem::PairTable table;
    const Index *count, *partner;
    dem::ContactHistory* history;
    const dem::WallPrimitive* prims;
    Index capacity;
    Real dt;
    DF_HD void operator()(Index i) const {
        const dem::GrainState si = dem::GrainState::load(g, i);
        Vec3 f{}, t{};
        for (Index k = 0; k < count[i]; ++k) {
            const Index s = i * capacity + k;
            const dem::GrainState sj = dem::GrainState::load(g, partner[s]);
            const Vec3 r = si.x - sj.x;
            const Real d2 = dot(r, r), rs = si.r + sj.r;
            if (d2 >= rs * rs) continue;
            const auto c = dem::grain_pair_force(table(si.material, sj.material), si, sj, r, d2, dt,
                                                 history[s]);
            f += c.force_i;
            t += c.torque_i;
        }
        const dem::WallPrimitive& w = prims[0];
        const Vec3 q = dem::closest_point(w, si.x);
        const Real d = dem::wall_distance(w, si.x, q);
        if (d < si.r) {
            dem::ContactHistory h{};
            const auto c = dem::wall_contact_force(table(si.material, si.material), si, w, q, d,
                                                   Vec3{}, dt, h);
            f += c.force;
            t += c.torque;
        }
        g.force[i] = f;
        g.torque[i] = t;
    }
};

// Rigid-body kinematics on the device: free rotation of every body and the motion of its
// boundary particles (the body Phase's loops).
struct RigidMotion {
    rigid::BodyState* bodies;
    const std::int32_t* owner;
    const Vec3* offset;
    Real *x, *y, *z, *vx, *vy, *vz;
    Real dt;
    DF_HD void operator()(Index i) const {
        rigid::BodyState& b = bodies[owner[i]];
        rigid::free_rotation(b.q, b.ang_mom, b.inv_inertia, dt);
        const Vec3 arm = rigid::rotate(b.q, offset[i]);
        const Vec3 v = b.vel + cross(b.omega(), arm);
        x[i] = b.pos.x + arm.x, y[i] = b.pos.y + arm.y, z[i] = b.pos.z + arm.z;
        vx[i] = v.x, vy[i] = v.y, vz[i] = v.z;
    }
};

// Drag coefficients of the unresolved SPH-DEM coupling, one grain per thread.
template <class Drag> struct GrainDrag {
    const Real *d, *rho, *mu, *slip, *eps;
    Real* beta;
    DF_HD void operator()(Index i) const {
        beta[i] = Drag::beta({d[i], rho[i], mu[i], slip[i], eps[i]});
    }
};

void instantiate_all() {
    launch(0, DemContacts{});
    launch(0, GrainDrag<coupling::DiFelice>{});
    launch(0, GrainDrag<coupling::SchillerNaumann>{});
    launch(0, RigidMotion{});
    instantiate_kernel<kernels::WendlandC2>();
    instantiate_kernel<kernels::CubicSpline>();
}

} // namespace debrisflow::cuda
