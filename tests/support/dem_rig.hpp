#pragma once
// A DEM system assembled directly (no case file) for contact-law tests.
#include "debrisflow/dem/dem_solver.hpp"
#include <cmath>
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
    // Adds a disc of a quasi-2D layer `thickness` thick (dim = 2) of material index mat.
    Index add_disc(Vec3 x, Real r, Real rho, Real thickness, int mat) {
        const Real m = rho * 3.14159265358979 * r * r * thickness;
        return grains.add(x, {}, r, m, 0.5 * m * r * r, std::uint8_t(mat));
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
    // The tilting table: gravity of magnitude g turns about y from beta0 [deg] at `rate` deg/s,
    // after `hold` s at beta0; returns the tilt [deg] at which `where()` has moved `distance`
    // from where it was at the end of the hold (90: not by 60 deg).
    template <class Where>
    Real tilt_until_moved(Real g, Real beta0, Real rate, Real hold, Real distance,
                          const Where& where) {
        auto gravity = [g](Real deg) {
            const Real b = deg * 3.14159265358979323846 / 180;
            return Vec3{g * std::sin(b), 0, -g * std::cos(b)};
        };
        solver->set_gravity(gravity(beta0));
        const Real h = solver->dt();
        Real t = 0;
        for (; t < hold; t += h) solver->advance(h);
        const Vec3 rest = where();
        for (Real beta = beta0; beta < 60; t += h) {
            beta = beta0 + rate * (t - hold);
            solver->set_gravity(gravity(beta));
            solver->advance(h);
            if (norm(where() - rest) > distance) return beta;
        }
        return 90;
    }
    void start(const dem::DemParams& params, std::vector<dem::Material> mats, Vec3 lo, Vec3 hi,
               const std::vector<dem::PairOverride>& overrides = {}) {
        Domain d;
        d.lo = lo;
        d.hi = hi;
        solver =
            std::make_unique<dem::DemSolver>(params, grains, walls, std::move(mats), overrides, d);
        solver->update_neighbors(true);
        solver->compute_forces();
    }
};

} // namespace debrisflow::test
