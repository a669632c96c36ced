#include "debrisflow/flow/outlet.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/sph/sph_solver.hpp"

namespace debrisflow::flow {

void Outlet::apply(sph::SphSolver* fluid, dem::DemSolver* grains) {
    if (fluid) {
        auto& s = fluid->particles();
        const Index n = s.size();
        std::vector<std::uint8_t> keep(std::size_t(n), 1);
        bool any = false;
        for (Index i = 0; i < n; ++i) {
            if (s.kind[i] != std::uint8_t(particles::Kind::fluid) ||
                !inside(s.x[i], s.y[i], s.z[i]))
                continue;
            keep[std::size_t(i)] = 0;
            any = true;
            fluid_mass_ += s.mass[i];
            fluid_volume_ += s.mass[i] / rho0_;
        }
        if (any) fluid->remove_particles(keep);
    }
    if (grains) {
        auto& g = grains->grains();
        const auto& mats = grains->materials();
        const Index n = g.size();
        std::vector<std::uint8_t> keep(std::size_t(n), 1);
        bool any = false;
        for (Index i = 0; i < n; ++i) {
            const Vec3 p = g.pos[std::size_t(i)];
            if (!inside(p.x, p.y, p.z)) continue;
            keep[std::size_t(i)] = 0;
            any = true;
            grain_mass_ += g.mass[std::size_t(i)];
            grain_volume_ += g.mass[std::size_t(i)] / mats[g.material[std::size_t(i)]].density;
            ++grains_removed_;
        }
        if (any) grains->remove_grains(keep);
    }
}

} // namespace debrisflow::flow
