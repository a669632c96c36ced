// The DEM contact-law registry: names, the index a pair stores, and the case reference's
// table of laws kept in step with it.
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
