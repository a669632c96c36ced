// The DEM contact-law registry: names, the index a pair stores, and the case reference's
// table of laws kept in step with it; the rolling-resistance registry likewise.
#include "debrisflow/dem/contact_force_k.hpp"
#include "debrisflow/dem/materials.hpp"
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace debrisflow;

TEST(ContactLawRegistry, NamesIndicesAndDispatchAgree) {
    using R = dem::ContactLawRegistry;
    EXPECT_EQ(R::names(),
              (std::vector<std::string>{"linear", "hertz_mindlin", "dcdem", "hertz_mindlin_jkr"}));
    std::size_t k = 0;
    R::for_each([&]<class L>() {
        EXPECT_EQ(R::index_of<L>(), k);
        EXPECT_EQ(R::visit_index(k, []<class M>() { return std::string(M::name); }), L::name);
        ++k;
    });
    // a pair table records the law's index
    dem::Material m;
    m.name = "a";
    m.law = "dcdem";
    m.youngs_modulus = 1e9;
    const auto table = dem::build_pair_table({m}, {}, "none");
    EXPECT_EQ(table[0].law, R::index_of<dem::DcdemLaw>());
}

// docs/case_reference.md has a row for every law (its table of laws and their own keys).
TEST(ContactLawRegistry, CaseReferenceListsEveryLaw) {
    std::ifstream in(DEBRISFLOW_SOURCE_DIR "/docs/case_reference.md");
    ASSERT_TRUE(in) << "docs/case_reference.md not found";
    std::stringstream text;
    text << in.rdbuf();
    for (const auto& name : dem::ContactLawRegistry::names())
        EXPECT_NE(text.str().find("| `" + name + "` |"), std::string::npos)
            << "no row for the law " << name;
}

// The rolling-resistance registry: names in the order a pair stores, and each model's moment
// for one contact against its closed form.
TEST(RollingRegistry, NamesAndMoments) {
    using R = dem::RollingRegistry;
    EXPECT_EQ(R::names(), (std::vector<std::string>{"none", "constant_torque", "epsd"}));
    dem::PairParams p;
    p.mu_roll = 0.1;
    // rolling about y at 2 rad/s on a contact with normal z; F_n = 50 N, R* = 0.01 m
    const dem::RollingInput in{{0.3, 2, 0.7}, {0, 0, 1}, 50, 1e6, 0.01, 1e-5};
    const Real m_max = 0.1 * 0.01 * 50; // mu_r R* F_n
    p.rolling = std::uint8_t(R::index_of<dem::NoRolling>());
    EXPECT_EQ(norm(dem::Rolling::moment(p, in, nullptr)), 0);
    // Zhou et al. 1999: M_r = -mu_r R* F_n w_r / |w_r|, w_r the in-plane part of w_rel
    p.rolling = std::uint8_t(R::index_of<dem::ConstantTorqueRolling>());
    const Vec3 mc = dem::Rolling::moment(p, in, nullptr);
    const Real wr = std::sqrt(0.3 * 0.3 + 2.0 * 2.0);
    EXPECT_NEAR(mc.x, -m_max * 0.3 / wr, 1e-15);
    EXPECT_NEAR(mc.y, -m_max * 2.0 / wr, 1e-15);
    EXPECT_EQ(mc.z, 0);
    // Ai et al. 2011: one step of the spring k_r = 2.25 k_n mu_r^2 R*^2 from rest, then capped
    p.rolling = std::uint8_t(R::index_of<dem::EpsdRolling>());
    const Real kr = 2.25 * 1e6 * 0.1 * 0.1 * 0.01 * 0.01;
    Vec3 memory{};
    const Vec3 me = dem::Rolling::moment(p, in, &memory);
    EXPECT_NEAR(me.y, -kr * 1e-5 * 2.0, 1e-15);
    EXPECT_EQ(memory.y, me.y);
    for (int k = 0; k < 100000; ++k) dem::Rolling::moment(p, in, &memory);
    EXPECT_NEAR(norm(memory), m_max, 1e-12); // |M_r| <= mu_r R* F_n
    EXPECT_GT(
        R::visit_index(p.rolling, [&]<class M>() { return M::mode_ratio(p, 0.01, 1e3, 0.1); }), 0);
}

// docs/case_reference.md names every rolling model in the dem.rolling row.
TEST(RollingRegistry, CaseReferenceNamesEveryModel) {
    std::ifstream in(DEBRISFLOW_SOURCE_DIR "/docs/case_reference.md");
    ASSERT_TRUE(in);
    std::string row;
    for (std::string line; std::getline(in, line);)
        if (line.rfind("| `dem.rolling` |", 0) == 0) row = line;
    ASSERT_FALSE(row.empty());
    for (const auto& name : dem::RollingRegistry::names())
        EXPECT_NE(row.find("`\"" + name + "\"`"), std::string::npos) << name;
}
