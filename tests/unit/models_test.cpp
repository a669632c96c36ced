// Models against their formulas: Tait EOS, registries, density diffusion at rest.
#include "debrisflow/models/eos_tait_k.hpp"
#include "debrisflow/sph/sph_models.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

TEST(TaitEos, PressureSoundSpeedAndInverse) {
    const models::TaitEos eos(1000, 20, 7);
    EXPECT_DOUBLE_EQ(eos.b, 20.0 * 20 * 1000 / 7);
    EXPECT_NEAR(eos.pressure(1010), eos.b * (std::pow(1.01, 7) - 1), 1e-9);
    EXPECT_NEAR(eos.sound_speed(1010), 20 * std::pow(1.01, 3), 1e-12);
    EXPECT_NEAR(eos.density(eos.pressure(1023.4)), 1023.4, 1e-9);
    const models::TaitEos general(1000, 20, 5);
    EXPECT_NEAR(general.pressure(1010), general.b * (std::pow(1.01, 5) - 1), 1e-9);
}

TEST(Registries, NamesAndChoices) {
    EXPECT_EQ(sph::ViscosityRegistry::names(),
              (std::vector<std::string>{"artificial", "laminar", "laminar_sps", "bingham",
                                        "herschel_bulkley", "mu_i", "carreau_yasuda"}));
    EXPECT_EQ(sph::DiffusionRegistry::names(),
              (std::vector<std::string>{"none", "molteni", "fourtakas", "antuono"}));
    EXPECT_TRUE(sph::DiffusionRegistry::has("fourtakas"));
}

// Fourtakas et al. 2019: the hydrostatic density difference is removed from the flux, which
// Molteni-Colagrossi keeps. The correction is linearised about rho0 (eq. 8), so at depth d it
// leaves a fraction 1 - (1 + p/B)^(1 - 1/gamma) of the flux: -7 % here (p/B = 0.086).
TEST(DensityDiffusion, FourtakasVanishesForHydrostaticState) {
    sph::SphParams p;
    p.c0 = 20;
    p.h = 0.015;
    p.diffusion = "fourtakas";
    const auto fourtakas = std::get<models::Fourtakas>(sph::SphModels::from_params(p).diffusion);
    p.diffusion = "molteni";
    const auto molteni =
        std::get<models::MolteniColagrossi>(sph::SphModels::from_params(p).diffusion);
    const models::TaitEos eos(1000, 20, 7);
    const double dz = 0.01, depth = 0.5;
    models::PairState s{};
    s.r = {0, 0, -dz}; // i below j
    s.r2 = dz * dz;
    s.f = -1e6;
    s.mass_j = 0.1;
    s.mass_i = 0.1;
    s.inv_r2_eta2 = 1 / (s.r2 + 0.01 * p.h * p.h);
    s.rho_i = eos.density(1000 * 9.81 * depth);
    s.rho_j = eos.density(1000 * 9.81 * (depth - dz));
    s.vol_i = s.mass_i / s.rho_i;
    s.vol_j = s.mass_j / s.rho_j;
    const double pb = 1000 * 9.81 * depth / eos.b;
    const double left = 1 - 1 / std::pow(1 + pb, 1.0 / 7 - 1);
    EXPECT_GT(std::abs(molteni.pair(s).i), 0);
    EXPECT_NEAR(fourtakas.pair(s).i / molteni.pair(s).i, left, 0.005);
    // Near the surface the flux vanishes.
    s.rho_i = eos.density(1000 * 9.81 * dz);
    s.rho_j = eos.density(0);
    s.vol_i = s.mass_i / s.rho_i;
    s.vol_j = s.mass_j / s.rho_j;
    EXPECT_NEAR(fourtakas.pair(s).i, 0, 0.01 * std::abs(molteni.pair(s).i));
}

// Papanastasiou (1987) regularised Bingham / Herschel-Bulkley: mu_app = K g^(n-1) +
// tau_y (1 - exp(-m g)) / g; the limit at rest is K + tau_y m (n = 1); capped at mu_max.
TEST(Rheology, HerschelBulkleyAndBinghamApparentViscosity) {
    models::BinghamViscosity b;
    b.consistency = 2, b.yield_stress = 10, b.regularization = 50, b.mu_max = 1e9;
    for (double g : {1e-3, 0.1, 1.0, 30.0})
        EXPECT_NEAR(b.apparent_viscosity(g, 0), 2 + 10 * (1 - std::exp(-50 * g)) / g,
                    1e-9 * b.apparent_viscosity(g, 0));
    EXPECT_NEAR(b.apparent_viscosity(0, 0), 2 + 10 * 50, 1e-9);
    EXPECT_NEAR(b.apparent_viscosity(1e-14, 0), 2 + 10 * 50, 1e-9); // no 0/0
    // Stress tends to the Bingham law mu_p g + tau_y once m g >> 1.
    EXPECT_NEAR(b.apparent_viscosity(5.0, 0) * 5.0, 2 * 5.0 + 10, 1e-9);
    b.mu_max = 100;
    EXPECT_DOUBLE_EQ(b.apparent_viscosity(0, 0), 100);

    models::HerschelBulkleyViscosity hb;
    hb.consistency = 3, hb.flow_index = 0.5, hb.yield_stress = 4, hb.regularization = 100;
    hb.mu_max = 1e6;
    for (double g : {0.01, 1.0, 16.0})
        EXPECT_NEAR(hb.apparent_viscosity(g, 0),
                    3 * std::pow(g, -0.5) + 4 * (1 - std::exp(-100 * g)) / g, 1e-9);
    EXPECT_DOUBLE_EQ(hb.apparent_viscosity(0, 0), 1e6); // shear thinning: capped at rest
}

// mu(I) (Jop, Forterre & Pouliquen 2006, eq. 2): mu = mu_s + (mu_2 - mu_s) / (I0 / I + 1),
// I = g d / sqrt(p / rho_s), apparent viscosity mu(I) p / g.
TEST(Rheology, MuOfIApparentViscosity) {
    models::MuIViscosity m;
    m.mu_s = 0.38, m.mu_2 = 0.64, m.i0 = 0.279, m.grain_diameter = 0.002, m.grain_density = 2600;
    m.mu_max = 1e9;
    const double p = 500, g = 20;
    const double I = g * 0.002 / std::sqrt(p / 2600);
    const double mu = 0.38 + 0.26 / (0.279 / I + 1);
    EXPECT_NEAR(m.apparent_viscosity(g, p), mu * p / g, 1e-9);
    EXPECT_DOUBLE_EQ(m.apparent_viscosity(g, -10), 0); // no strength without pressure
    m.mu_base = 0.01;
    EXPECT_DOUBLE_EQ(m.apparent_viscosity(g, 0), 0.01);
    m.mu_max = 5;
    EXPECT_DOUBLE_EQ(m.apparent_viscosity(1e-6, p), 5);
}
