// The order of the phases in a step (coupling/step_order.hpp) and what the couplings state
// they exchange (coupling/coupling.hpp).
#include "debrisflow/coupling/step_order.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace debrisflow;

namespace {

// A phase that has a name and does nothing.
class NamedPhase : public time::Phase {
public:
    explicit NamedPhase(const char* name) : name_(name) {}
    const char* name() const override { return name_; }
    void update_neighbors(bool) override {}
    void compute_forces() override {}
    void predictor(Real) override {}
    void corrector(Real) override {}
    void verlet_step(Real, bool) override {}
    time::DtLimit stable_dt() const override { return {1, name_}; }
    void check_health(Real) const override {}
    void add_timings(time::Timings&) const override {}

private:
    const char* name_;
};

std::size_t position(const std::vector<time::Phase*>& order, const std::string& name) {
    for (std::size_t k = 0; k < order.size(); ++k)
        if (order[k]->name() == name) return k;
    return order.size();
}

const std::vector<std::string> phase_names = {"sph", "dem", "sph-dem", "rigid", "fem"};

} // namespace

// Every subset of the phases, handed over in reverse order, comes out with every rule holding
// and nothing lost or added.
TEST(CouplingOrder, EveryRuleHoldsForEverySubsetInAnyGivenOrder) {
    std::vector<NamedPhase> all;
    for (const auto& n : phase_names) all.emplace_back(n.c_str());
    for (unsigned mask = 1; mask < (1u << all.size()); ++mask) {
        std::vector<time::Phase*> given;
        for (std::size_t k = all.size(); k-- > 0;)
            if (mask & (1u << k)) given.push_back(&all[k]);
        given.insert(given.begin() + 1, nullptr); // absent solvers are null
        const auto order = coupling::force_order(given);
        ASSERT_EQ(order.size(), std::size_t(std::popcount(mask)));
        for (const auto& r : coupling::order_rules()) {
            const std::size_t b = position(order, r.before), a = position(order, r.after);
            if (b < order.size() && a < order.size())
                EXPECT_LT(b, a) << r.before << " before " << r.after << " (" << r.why << ")";
        }
    }
}

// The phases no rule relates keep the order they were given in.
TEST(CouplingOrder, StableForPhasesNoRuleRelates) {
    NamedPhase sph("sph"), dem("dem"), sph_dem("sph-dem"), rigid("rigid"), fem("fem");
    const auto natural = coupling::force_order({&sph, &dem, &sph_dem, &rigid, &fem});
    EXPECT_EQ(natural, (std::vector<time::Phase*>{&sph, &dem, &sph_dem, &rigid, &fem}));
    const auto swapped = coupling::force_order({&dem, &sph});
    EXPECT_EQ(swapped, (std::vector<time::Phase*>{&dem, &sph}));
    const auto reversed = coupling::force_order({&fem, &rigid, &sph_dem, &dem, &sph});
    for (const char* first : {"sph", "dem", "rigid"})
        EXPECT_GT(position(reversed, "fem"), position(reversed, first)) << first;
    EXPECT_GT(position(reversed, "sph-dem"), position(reversed, "sph"));
    EXPECT_GT(position(reversed, "sph-dem"), position(reversed, "dem"));
}

// Every rule names known phases and says why.
TEST(CouplingOrder, RulesNameKnownPhases) {
    const std::set<std::string> known(phase_names.begin(), phase_names.end());
    for (const auto& r : coupling::order_rules()) {
        EXPECT_TRUE(known.count(r.before)) << r.before;
        EXPECT_TRUE(known.count(r.after)) << r.after;
        EXPECT_GT(std::string(r.why).size(), 20u);
    }
}

// A case with fluid, grains and the fluid drag: the SPH-DEM coupling is a phase after the SPH
// and DEM phases, and every exchange it states is backed by an order rule from its source.
TEST(CouplingOrder, FluidGrainCouplingStatesItsExchanges) {
    const std::string toml = R"(
name = "coupling_order"
dimensions = 3
dp = 0.02
[time]
end = 0.01
[output]
vtk = false
[physics]
gravity = [0, 0, 0]
[domain]
min = [0, 0, 0]
max = [0.2, 0.2, 0.2]
periodic = ["x", "y", "z"]
[sph]
rho0 = 1000
c0 = 5
viscosity = "laminar"
nu = 1e-2
[[fluid]]
name = "water"
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.2, 0.2, 0.2]
[[material]]
name = "sand"
density = 2650
law = "hertz_mindlin"
youngs_modulus = 1e7
poisson = 0.3
restitution = 0.5
friction = 0.3
[[grains]]
name = "a"
material = "sand"
packing = "single"
position = [0.05, 0.1, 0.1]
diameter = 0.005
[dem]
fluid_drag = "di_felice"
reference_velocity = 1.0
)";
    app::Simulation sim(test::case_from_toml("coupling_order", toml));
    const auto couplings = sim.couplings();
    ASSERT_EQ(couplings.size(), 1u);
    const coupling::Coupling& c = *couplings[0];
    EXPECT_STREQ(c.coupling_name(), "sph-dem");
    const auto ex = c.exchanges();
    ASSERT_EQ(ex.size(), 2u);
    std::set<std::string> sources;
    for (const auto& e : ex) {
        EXPECT_EQ(e.when, coupling::When::force_evaluation);
        EXPECT_NE(e.from, e.to);
        sources.insert(e.from);
        EXPECT_FALSE(coupling::describe(e).empty());
    }
    EXPECT_EQ(sources, (std::set<std::string>{"sph", "dem"}));
    for (const auto& s : sources)
        EXPECT_TRUE(std::any_of(coupling::order_rules().begin(), coupling::order_rules().end(),
                                [&](const coupling::OrderRule& r) {
                                    return r.before == s && std::string(r.after) == "sph-dem";
                                }))
            << s;
}
