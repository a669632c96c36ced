#include "debrisflow/flow/outlet.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/sph/sph_solver.hpp"

namespace debrisflow::flow {

void Outlet::tally_fluid(const std::vector<Real>& masses) {
    for (const Real m : masses) {
        fluid_mass_ += m;
        fluid_volume_ += m / rho0_;
    }
}

void Outlet::tally_grains(const std::vector<Real>& masses,
                          const std::vector<std::uint8_t>& materials,
                          const std::vector<dem::Material>& mats) {
    for (std::size_t k = 0; k < masses.size(); ++k) {
        grain_mass_ += masses[k];
        grain_volume_ += masses[k] / mats[materials[k]].density;
        ++grains_removed_;
    }
}

void Outlet::apply(sph::SphSolver* fluid, dem::DemSolver* grains, rigid::BodySolver* bodies) {
    if (fluid) {
        auto& s = fluid->particles();
        const Index n = s.size();
        std::vector<std::uint8_t> keep(std::size_t(n), 1);
        std::vector<Real> removed;
        for (Index i = 0; i < n; ++i) {
            if (s.kind[i] != std::uint8_t(particles::Kind::fluid) ||
                !inside(s.x[i], s.y[i], s.z[i]))
                continue;
            keep[std::size_t(i)] = 0;
            removed.push_back(s.mass[i]);
        }
        tally_fluid(removed);
        if (!removed.empty()) fluid->remove_particles(keep);
    }
    if (grains) {
        auto& g = grains->grains();
        const Index n = g.size();
        std::vector<std::uint8_t> keep(std::size_t(n), 1);
        bool any = false;
        for (Index i = 0; i < n; ++i) {
            const Vec3 p = g.pos[std::size_t(i)];
            if (!inside(p.x, p.y, p.z)) continue;
            keep[std::size_t(i)] = 0;
            any = true;
        }
        if (any) {
            grains->expand_to_clumps(keep); // a clump with a member inside leaves whole
            std::vector<Real> masses;
            std::vector<std::uint8_t> materials;
            for (Index i = 0; i < n; ++i) {
                if (keep[std::size_t(i)]) continue;
                masses.push_back(g.mass[std::size_t(i)]);
                materials.push_back(g.material[std::size_t(i)]);
            }
            tally_grains(masses, materials, grains->materials());
            grains->remove_grains(keep);
        }
    }
    if (bodies) {
        std::vector<std::uint8_t> keep; // the removed bodies' SPH boundary particles
        for (std::size_t b = 0; b < bodies->bodies().size(); ++b) {
            const rigid::BodyState& s = bodies->bodies()[b];
            if (s.motion != rigid::Motion::free || !inside(s.pos.x, s.pos.y, s.pos.z)) continue;
            const Real mass = s.mass;
            if (!bodies->remove_body(int(b), keep)) continue;
            body_mass_ += mass;
            ++bodies_removed_;
        }
        if (!keep.empty() && fluid) fluid->remove_particles(keep);
    }
}

} // namespace debrisflow::flow
