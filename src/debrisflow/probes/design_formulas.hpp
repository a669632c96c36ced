#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/probes/probe.hpp"
#include <memory>
#include <string>
#include <vector>

namespace debrisflow::probes {

// Design-formula companions of a measured peak wall load (wall_force probe with `approach`
// and/or `boulder`):
//  - hydrodynamic F = alpha rho v^2 h w (e.g. Hungr et al. 1984; Kwan 2012, GEO Report 270):
//    alpha back-calculated from the peak normal load and the approach flow's largest momentum
//    flux rho v^2 h (flow_section: rho0 unless given; section: the measured bulk density);
//  - Hertz boulder impact (Johnson 1985, sphere on a half-space): delta = (15 m v^2 /
//    (16 E* r^0.5))^0.4, F = 4/3 E* r^0.5 delta^1.5, with the body's mass, equivalent-sphere
//    radius and peak speed; the design value K_c F (Kwan 2012, K_c = 0.1) beside the measured
//    peak of the bodies' contact load.
struct DesignCheck {
    std::string probe;
    Real f_peak = 0, f_peak_time = 0; // measured peak normal load [N] (2D: N/m)
    bool hydro = false;
    Real rho = 0, v = 0, h = 0, w = 0, alpha = 0;
    bool hertz = false;
    Real mass = 0, radius = 0, v_impact = 0, e_star = 0, k_c = 0, f_hertz = 0, f_bodies_peak = 0;
    std::string note; // why a formula could not be evaluated
};

struct BodyInfo {
    std::string name;
    Real mass, volume;
    int material;
};

std::vector<DesignCheck> design_checks(const io::CaseSpec& c,
                                       const std::vector<std::unique_ptr<Probe>>& probes,
                                       const std::vector<BodyInfo>& bodies);

// Hertz peak force of a sphere (mass m, radius r) hitting a flat at speed v.
Real hertz_impact_force(Real m, Real r, Real v, Real e_star);

} // namespace debrisflow::probes
