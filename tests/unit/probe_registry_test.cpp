// The probe registry: every type a [[probe]] block can name reads its own keys when the probe
// is made, and the case reference lists every type.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/probes/probe_registry.hpp"
#include "run_case.hpp"
#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sstream>

using namespace debrisflow;

namespace {
// A small 2D tank of water with walls, grains absent.
const char* tank = R"(
name = "probe_registry"
dimensions = 2
dp = 0.02
[time]
end = 0.01
[domain]
min = [-0.1, -0.1]
max = [1.1, 1.0]
[sph]
reference_depth = 0.3
c0_coefficient = 10
[[fluid]]
name = "water"
shape = "box"
min = [0.0, 0.0]
max = [0.4, 0.3]
[[wall]]
name = "tank"
shape = "open_tank"
min = [0.0, 0.0]
max = [1.0, 0.8]
)";

std::string error_of(const std::string& probe) {
    return test::input_error_of("probe_registry", std::string(tank) + "[[probe]]\n" + probe);
}
} // namespace

TEST(ProbeRegistry, NamesAreUniqueAndEachMakesItsProbe) {
    std::set<std::string> seen;
    for (const auto& type : probes::probe_types()) {
        EXPECT_TRUE(seen.insert(std::string(type.name)).second) << type.name;
        EXPECT_NE(type.from_config, nullptr) << type.name;
    }
    EXPECT_EQ(seen.size(), 22u);
    // two fluid probes made through the registry, with the keys they read
    const auto spec = test::case_from_toml(
        "probe_registry",
        std::string(tank) +
            "[[probe]]\nname = \"p\"\ntype = \"pressure\"\nposition = [0.5, "
            "0.01]\n[[probe]]\nname = \"front\"\ntype = \"front\"\naxis = \"-x\"\n");
    app::Simulation sim(spec);
    EXPECT_EQ(sim.probe("p").columns(), std::vector<std::string>{"p [Pa]"});
    EXPECT_EQ(sim.probe("front").columns(), std::vector<std::string>{"x_front [m]"});
}

TEST(ProbeRegistry, ATypeRejectsWhatItDoesNotRead) {
    // an unknown type is named with the file and key, not taken for a wall probe
    const std::string tank_text = tank;
    const long type_line = std::count(tank_text.begin(), tank_text.end(), '\n') + 3;
    const std::string unknown = error_of("name = \"a\"\ntype = \"wall_forces\"\nwall = \"tank\"\n");
    EXPECT_NE(unknown.find("probe_registry.toml:" + std::to_string(type_line) +
                           ":8: key 'probe.0.type': unknown choice \"wall_forces\""),
              std::string::npos)
        << unknown;
    // a key of another type is unknown to this one
    EXPECT_NE(error_of("name = \"a\"\ntype = \"deposit\"\nmin = [0, 0]\nmax = [1, 1]\nbed = 0\n")
                  .find("unknown key 'probe.0.bed'"),
              std::string::npos);
    // each type checks its own values
    EXPECT_NE(error_of("name = \"a\"\ntype = \"pressure_map\"\nwall = \"tank\"\naxis = \"x\"\n"
                       "normal = [1, 0]\npanels = [1e9, 1]\n")
                  .find("key 'probe.0.panels': expected [n_u, n_v] panels over the face"),
              std::string::npos);
    EXPECT_NE(error_of("name = \"a\"\ntype = \"runup\"\nwall = \"tank\"\n")
                  .find("a runup probe needs [[grains]]"),
              std::string::npos);
    // a design companion must name a probe above it
    EXPECT_NE(error_of("name = \"a\"\ntype = \"wall_force\"\nwall = \"tank\"\nnormal = [1, 0]\n"
                       "approach = \"b\"\nwidth = 1\n")
                  .find("no flow_section or section probe named \"b\" above this one"),
              std::string::npos);
}

// docs/case_reference.md's table of what each probe reads lists every type.
TEST(ProbeRegistry, CaseReferenceListsEveryType) {
    std::ifstream in(DEBRISFLOW_SOURCE_DIR "/docs/case_reference.md");
    ASSERT_TRUE(in) << "docs/case_reference.md not found";
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const auto table = doc.find("| probe | what it measures |");
    ASSERT_NE(table, std::string::npos);
    std::set<std::string> listed;
    std::istringstream rows(doc.substr(table));
    for (std::string row; std::getline(rows, row) && row.rfind("|", 0) == 0;) {
        const std::string first = row.substr(1, row.find('|', 1) - 1);
        for (auto a = first.find('`'); a != std::string::npos; a = first.find('`', a + 1)) {
            const auto b = first.find('`', a + 1);
            listed.insert(first.substr(a + 1, b - a - 1));
            a = b;
        }
    }
    for (const auto& type : probes::probe_types())
        EXPECT_TRUE(listed.count(std::string(type.name)))
            << "no row for the probe type " << type.name;
}
