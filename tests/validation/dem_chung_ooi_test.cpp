// Chung & Ooi (2011, Granular Matter 13:643) DEM benchmarks 1-3: normal impacts against the
// Hertz solution (Johnson 1985) in ../shared/reference/analytic/hertz_chung_ooi_T1_T3.csv, the
// restitution of the damped laws, and the exact linear oscillator.
#include "dem_rig.hpp"
#include "reference_data.hpp"
#include "run_case.hpp"
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace debrisflow;
using test::DemRig;

namespace {

struct HertzRow {
    std::string name;
    Real r, rho, e, nu, v, dmax_um, fmax_kn, tc_us;
};

std::vector<HertzRow> hertz_rows() {
    std::ifstream in(test::reference("analytic/hertz_chung_ooi_T1_T3.csv"));
    EXPECT_TRUE(in.good());
    std::string line;
    std::getline(in, line);
    std::vector<HertzRow> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::string f[12];
        for (auto& x : f) std::getline(s, x, ',');
        rows.push_back({f[0], std::stod(f[1]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4]),
                        std::stod(f[5]), std::stod(f[9]), std::stod(f[10]), std::stod(f[11])});
    }
    return rows;
}

// Peak normal force, largest overlap, contact duration (end points interpolated) and the
// rebound speed of a normal impact.
struct Impact {
    Real fmax = 0, dmax = 0, duration = 0, rebound = 0;
};

Index index_of(const dem::GrainSet& g, std::uint32_t id) {
    for (Index i = 0; i < g.size(); ++i)
        if (g.id[std::size_t(i)] == id) return i;
    return -1;
}

// Two equal spheres approaching each other at v each (wall = false), or one sphere hitting a
// rigid plane at v (wall = true), along z without gravity.
Impact normal_impact(const dem::Material& m, Real r, Real v, bool wall, Real dt_fraction,
                     Real expected_tc) {
    DemRig rig;
    std::vector<dem::Material> mats{m};
    const Real gap = 1e-3 * r;
    if (wall) {
        dem::Material rigid = m;
        rigid.name = "rigid";
        rigid.rigid = true;
        mats.push_back(rigid);
        rig.add_sphere({0, 0, r + gap}, {0, 0, -v}, r, m.density, 0);
        rig.add_plane("floor", {0, 0, 0}, {0, 0, 1}, 1);
    } else {
        rig.add_sphere({0, 0, -r - gap / 2}, {0, 0, v}, r, m.density, 0);
        rig.add_sphere({0, 0, r + gap / 2}, {0, 0, -v}, r, m.density, 0);
    }
    dem::DemParams p;
    p.gravity = {0, 0, 0};
    p.dt = dt_fraction * expected_tc;
    rig.start(p, mats, {-4 * r, -4 * r, -4 * r}, {4 * r, 4 * r, 4 * r});
    Impact out;
    const Real dt = p.dt;
    auto overlap = [&]() {
        const auto& g = rig.grains;
        if (wall) return r - g.pos[0].z;
        const Index a = index_of(g, 0), b = index_of(g, 1);
        return 2 * r - (g.pos[std::size_t(b)].z - g.pos[std::size_t(a)].z);
    };
    Real t = 0, prev = overlap(), t_in = -1;
    for (long s = 0; s < long(4 * expected_tc / dt) + long(gap / v / dt) * 2 + 100; ++s) {
        rig.solver->advance(dt);
        t += dt;
        const Real d = overlap();
        const Index top = wall ? 0 : index_of(rig.grains, 1);
        out.fmax = std::max(out.fmax, std::fabs(rig.grains.force[std::size_t(top)].z));
        out.dmax = std::max(out.dmax, d);
        if (prev <= 0 && d > 0) t_in = t - dt + dt * (-prev) / (d - prev);
        if (prev > 0 && d <= 0 && t_in >= 0) {
            out.duration = t - dt + dt * prev / (prev - d) - t_in;
            out.rebound = rig.grains.vel[std::size_t(top)].z;
            break;
        }
        prev = d;
    }
    return out;
}

dem::Material hertz_material(const HertzRow& row, Real e) {
    dem::Material m;
    m.name = row.name;
    m.law = "hertz_mindlin";
    m.density = row.rho;
    m.youngs_modulus = row.e;
    m.poisson = row.nu;
    m.restitution = e;
    m.friction = 0;
    return m;
}

} // namespace

// Tests 1 and 2: elastic normal impacts (glass and limestone sphere pairs; Al and Mg alloy
// spheres on a rigid wall). Tolerance 1 % on peak force, largest overlap and contact time
// (issue 3; the Hertz values are exact, the error is the time integration's).
TEST(DemChungOoi, ElasticNormalImpactMatchesHertz) {
    for (const auto& row : hertz_rows()) {
        if (row.name.rfind("T3", 0) == 0) continue;
        const bool wall = row.name.find("wall") != std::string::npos;
        const Real v = wall ? row.v : row.v / 2;
        const Impact im =
            normal_impact(hertz_material(row, 1), row.r, v, wall, 1e-3, row.tc_us * 1e-6);
        SCOPED_TRACE(row.name);
        EXPECT_NEAR(im.fmax / (row.fmax_kn * 1e3), 1, 0.01);
        EXPECT_NEAR(im.dmax / (row.dmax_um * 1e-6), 1, 0.01);
        EXPECT_NEAR(im.duration / (row.tc_us * 1e-6), 1, 0.01);
        EXPECT_NEAR(std::fabs(im.rebound) / v, 1, 0.01); // elastic: energy conserved
    }
}

// Test 3: Al oxide and cast iron spheres on a rigid wall at 3.9 m/s; with e = 1 the Hertz
// values within 1 %, and for e = 0.2 ... 1.0 the output restitution equals the input within 1 %.
TEST(DemChungOoi, DampedImpactRestitutionEqualsInput) {
    for (const auto& row : hertz_rows()) {
        if (row.name.rfind("T3", 0) != 0) continue;
        SCOPED_TRACE(row.name);
        const Impact el =
            normal_impact(hertz_material(row, 1), row.r, row.v, true, 1e-3, row.tc_us * 1e-6);
        EXPECT_NEAR(el.fmax / (row.fmax_kn * 1e3), 1, 0.01);
        EXPECT_NEAR(el.dmax / (row.dmax_um * 1e-6), 1, 0.01);
        EXPECT_NEAR(el.duration / (row.tc_us * 1e-6), 1, 0.01);
        for (Real e : {0.2, 0.4, 0.6, 0.8, 1.0}) {
            const Impact im =
                normal_impact(hertz_material(row, e), row.r, row.v, true, 1e-3, row.tc_us * 1e-6);
            EXPECT_NEAR(im.rebound / row.v / e, 1, 0.01) << "e = " << e;
        }
    }
}

// Linear spring-dashpot: contact time pi / (w0 sqrt(1 - zeta^2)) and restitution e are exact
// (tolerance 0.1 %, the time-integration error at dt = t_c / 1000).
TEST(DemChungOoi, LinearLawContactTimeAndRestitutionExact) {
    const Real r = 0.005, rho = 2550, kn = 1e8;
    for (Real e : {0.3, 0.78, 1.0}) {
        dem::Material m;
        m.name = "glass";
        m.density = rho;
        m.kn = m.kt = kn;
        m.restitution = e;
        m.friction = 0;
        const Real mass = DemRig::sphere_mass(rho, r);
        const Real zeta = dem::linear_damping_ratio(e);
        const Real tc = 3.14159265358979 / (std::sqrt(kn / mass) * std::sqrt(1 - zeta * zeta));
        const Impact im = normal_impact(m, r, 1.0, true, 1e-3, tc);
        SCOPED_TRACE(e);
        EXPECT_NEAR(im.duration / tc, 1, 0.001);
        EXPECT_NEAR(im.rebound / e, 1, 0.001);
    }
}
