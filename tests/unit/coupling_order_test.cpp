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
            if (b < order.size() && a < order.size()) {
                EXPECT_LT(b, a) << r.before << " before " << r.after << " (" << r.why << ")";
            }
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

namespace {
// What backs an exchange in the force evaluation: a rule that puts its source before its
// destination, or before the coupling's own phase (sph-dem is a phase).
bool backed_by_rule(const coupling::Exchange& e, const std::string& coupling_phase) {
    const auto& rules = coupling::order_rules();
    return std::any_of(rules.begin(), rules.end(), [&](const coupling::OrderRule& r) {
        return r.before == e.from && (r.after == e.to || r.after == coupling_phase);
    });
}
} // namespace

// A case with fluid, grains (with the fluid drag) and a floating body: the sph-dem, sph-rigid
// and dem-rigid couplings state their exchanges; each goes from one model to another, both
// directions are there, and every exchange in the force evaluation is backed by an order rule.
TEST(CouplingOrder, CouplingsStateTheirExchanges) {
    const std::string toml = R"(
name = "coupling_order"
dimensions = 3
dp = 0.02
[time]
end = 0.01
[output]
vtk = false
[domain]
min = [-0.1, -0.1, -0.1]
max = [0.4, 0.4, 0.4]
[sph]
rho0 = 1000
c0 = 10
viscosity = "laminar"
nu = 1e-3
[[fluid]]
name = "water"
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.3, 0.3, 0.2]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0.0, 0.0, 0.0]
max = [0.3, 0.3, 0.3]
[[material]]
name = "gravel"
density = 2650
law = "linear"
kn = 1e4
restitution = 0.5
friction = 0.4
[[grains]]
name = "stone"
material = "gravel"
packing = "single"
position = [0.1, 0.15, 0.1]
diameter = 0.01
[dem]
fluid_drag = "di_felice"
reference_velocity = 1.0
[[body]]
name = "log"
material = "gravel"
density = 500
shape = "box"
min = [0.18, 0.1, 0.16]
max = [0.26, 0.2, 0.24]
)";
    app::Simulation sim(test::case_from_toml("coupling_order", toml));
    std::set<std::string> names;
    for (const coupling::Coupling* c : sim.couplings()) {
        names.insert(c->coupling_name());
        std::set<std::pair<std::string, std::string>> directions;
        for (const auto& e : c->exchanges()) {
            EXPECT_NE(e.from, e.to) << coupling::describe(e);
            EXPECT_FALSE(e.what.empty());
            directions.insert({e.from, e.to});
            if (e.when == coupling::When::force_evaluation) {
                EXPECT_TRUE(backed_by_rule(e, c->coupling_name())) << coupling::describe(e);
            }
        }
        for (const auto& [from, to] : directions) // two-way
            EXPECT_TRUE(directions.count({to, from})) << c->coupling_name() << ": " << from;
    }
    EXPECT_EQ(names, (std::set<std::string>{"sph-dem", "sph-rigid", "dem-rigid"}));
}
