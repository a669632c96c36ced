#include "debrisflow/flow/fluid_inlet.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include <cmath>

namespace debrisflow::flow {

FluidInlet::FluidInlet(const io::InletSpec& spec, const io::CaseSpec& c)
    : spec_(spec), q_{spec.times, spec.discharge}, eos_(c.sph.rho0, c.sph.c0, c.sph.gamma),
      dp_(c.dp), rho0_(c.sph.rho0), area_(spec.area(c.dim)),
      g_down_(c.sph.gravity.z < 0 ? -c.sph.gravity.z : 0), dim_(c.dim),
      group_(std::int16_t(spec.fluid)) {}

InletBuffer FluidInlet::buffer(Real t) const {
    return {spec_.min, spec_.max, spec_.axis, Real(spec_.sign) * velocity(t),
            g_down_,   dim_ == 2, eos_};
}

void FluidInlet::add_layer(std::vector<particles::NewParticle>& out, Real along, Real t) {
    const int a = spec_.axis;
    int perp[2], np = 0;
    for (int k = 0; k < 3; ++k)
        if (k != a && !(dim_ == 2 && k == 1)) perp[np++] = k;
    const InletBuffer state = buffer(t);
    Vec3 vel{};
    vel[a] = state.velocity;
    auto count = [&](int k) { return int(std::floor((spec_.max[k] - spec_.min[k]) / dp_ + 1e-9)); };
    const int n0 = count(perp[0]), n1 = np > 1 ? count(perp[1]) : 1;
    const Real cell = sph::lattice_volume(dp_, dim_);
    for (int i = 0; i < n0; ++i)
        for (int j = 0; j < n1; ++j) {
            Vec3 x{};
            x[a] = along;
            x[perp[0]] = spec_.min[perp[0]] + (i + Real(0.5)) * dp_;
            if (np > 1) x[perp[1]] = spec_.min[perp[1]] + (j + Real(0.5)) * dp_;
            const Real rho = state.density_at(x.z);
            out.push_back({x, vel, rho, rho * cell, particles::Kind::fluid, group_});
            mass_in_ += rho * cell;
            volume_in_ += cell * rho / rho0_;
        }
}

std::vector<particles::NewParticle> FluidInlet::new_layers(Real t, Real dt) {
    // New layers behind the upstream one: it started at dp/2 inside the upstream face.
    const int a = spec_.axis;
    std::vector<particles::NewParticle> out;
    advance_ += velocity(t) * dt;
    const Real upstream = spec_.sign > 0 ? spec_.min[a] : spec_.max[a];
    while (advance_ >= dp_) {
        advance_ -= dp_;
        add_layer(out, upstream + Real(spec_.sign) * (Real(0.5) * dp_ + advance_), t);
    }
    return out;
}

void FluidInlet::apply(particles::ParticleSet& set, Real t, Real dt) {
    const bool old = set.keeps_previous_state(); // Verlet only
    exec::for_each(set.size(),
                   PrescribeBuffer{buffer(t), set.view(), old ? set.vx_old.data() : nullptr,
                                   old ? set.vy_old.data() : nullptr,
                                   old ? set.vz_old.data() : nullptr,
                                   old ? set.rho_old.data() : nullptr});
    for (const auto& q : new_layers(t, dt)) set.add(q);
}

} // namespace debrisflow::flow
