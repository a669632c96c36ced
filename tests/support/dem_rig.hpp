#pragma once
// A DEM system assembled directly (no case file) for contact-law tests.
#include "debrisflow/dem/dem_solver.hpp"
#include <memory>

namespace debrisflow::test {

struct DemRig {
    dem::GrainSet grains;
    dem::WallSet walls;
    std::unique_ptr<dem::DemSolver> solver;

    static Real sphere_mass(Real rho, Real r) {
        return rho * 4.0 / 3.0 * 3.14159265358979 * r * r * r;
    }
    // Adds a solid sphere of material index mat.
    Index add_sphere(Vec3 x, Vec3 v, Real r, Real rho, int mat) {
        const Real m = sphere_mass(rho, r);
        return grains.add(x, v, r, m, 0.4 * m * r * r, std::uint8_t(mat));
    }
    void add_plane(const std::string& name, Vec3 point, Vec3 normal, int material) {
        dem::Wall w;
        w.name = name;
        w.material = material;
        dem::WallPrimitive p{point, {}, {}, normal, dem::PrimitiveType::plane, 0};
        walls.add(w, {p});
    }
    // Runs to t_end and returns the least-squares slope of grain 0's v_x over [t_fit, t_end]:
    // its acceleration along x.
    Real fitted_acceleration(Real t_fit, Real t_end) {
        Real st = 0, sv = 0, stt = 0, stv = 0, t = 0;
        long n = 0;
        while (t < t_end) {
            solver->advance(solver->dt());
            t += solver->dt();
            if (t < t_fit) continue;
            const Real v = grains.vel[0].x;
            st += t, sv += v, stt += t * t, stv += t * v;
            ++n;
        }
        return (Real(n) * stv - st * sv) / (Real(n) * stt - st * st);
    }
    void start(const dem::DemParams& params, std::vector<dem::Material> mats, Vec3 lo, Vec3 hi,
               const std::vector<dem::PairOverride>& overrides = {}) {
        sph::Domain d;
        d.lo = lo;
        d.hi = hi;
        solver =
            std::make_unique<dem::DemSolver>(params, grains, walls, std::move(mats), overrides, d);
        solver->update_neighbors(true);
        solver->compute_forces();
    }
};

} // namespace debrisflow::test
