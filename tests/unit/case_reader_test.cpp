// Case files: errors name file:line:column and the key; --set overrides any key.
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/io/config_table.hpp"
#include "debrisflow/io/toml_echo.hpp"
#include "run_case.hpp"
#include <filesystem>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

const char* minimal = R"(dp = 0.01
[time]
end = 0.1
[domain]
min = [-0.1, -0.1]
max = [1.0, 1.0]
[sph]
c0 = 20
[[fluid]]
name = "water"
shape = "box"
min = [0, 0]
max = [0.2, 0.2]
)";

std::string error_of(const std::string& toml, const std::vector<std::string>& sets = {}) {
    try {
        test::case_from_toml("case_reader", toml, sets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CaseReader, MinimalCaseReads) {
    const auto c = test::case_from_toml("minimal", minimal);
    EXPECT_EQ(c.dim, 2);
    EXPECT_DOUBLE_EQ(c.dp, 0.01);
    EXPECT_DOUBLE_EQ(c.sph.h, 0.015); // Wendland default h = 1.5 dp
    EXPECT_EQ(c.sph.viscosity, "artificial");
}

TEST(CaseReader, UnknownKeyNamesLineColumnAndSuggestion) {
    const std::string e = error_of(std::string(minimal) + "[output]\nvtk_evry = 0.1\n");
    EXPECT_NE(e.find("case_reader.toml:15:"), std::string::npos) << e;
    EXPECT_NE(e.find("output.vtk_evry"), std::string::npos) << e;
    EXPECT_NE(e.find("did you mean 'vtk_every'"), std::string::npos) << e;
}

TEST(CaseReader, WrongTypeAndImpossibleValue) {
    std::string bad = minimal;
    bad.replace(bad.find("c0 = 20"), 7, "c0 = \"fast\"");
    std::string e = error_of(bad);
    EXPECT_NE(e.find("case_reader.toml:8:6: key 'sph.c0'"), std::string::npos) << e;
    EXPECT_NE(e.find("expected a number"), std::string::npos) << e;
    e = error_of(minimal, {"dp=-1"});
    EXPECT_NE(e.find("key 'dp'"), std::string::npos) << e;
    EXPECT_NE(e.find("must be > 0"), std::string::npos) << e;
}

TEST(CaseReader, MissingKeyAndUnknownModel) {
    std::string bad = minimal;
    bad.replace(bad.find("dp = 0.01"), 9, "");
    EXPECT_NE(error_of(bad).find("missing required key 'dp'"), std::string::npos);
    const std::string e = error_of(minimal, {"sph.viscosity=\"magic\""});
    EXPECT_NE(e.find("unknown choice \"magic\""), std::string::npos) << e;
    EXPECT_NE(e.find("\"laminar_sps\""), std::string::npos) << e;
}

TEST(CaseReader, OverridesApply) {
    const auto c = test::case_from_toml(
        "overrides", minimal,
        {"time.end=0.05", "dp=0.005", "fluid.0.max=[0.3, 0.1]", "sph.kernel=cubic_spline"});
    EXPECT_DOUBLE_EQ(c.t_end, 0.05);
    EXPECT_DOUBLE_EQ(c.dp, 0.005);
    EXPECT_DOUBLE_EQ(c.fluids[0].shape.max.x, 0.3);
    EXPECT_EQ(c.sph.kernel, "cubic_spline");
    EXPECT_NEAR(c.sph.h, std::sqrt(3.0) * 0.005, 1e-15);
    EXPECT_NE(error_of(minimal, {"fluid.3.max=[1,1]"}).find("out of range"), std::string::npos);
    EXPECT_NE(error_of(minimal, {"sph.colour=1"}).find("unknown key 'sph.colour'"),
              std::string::npos);
}

TEST(CaseReader, C0FromCoefficient) {
    std::string s = minimal;
    s.replace(s.find("c0 = 20"), 7, "c0_coefficient = 10\nreference_depth = 0.3");
    const auto c = test::case_from_toml("c0coef", s);
    EXPECT_NEAR(c.sph.c0, 10 * std::sqrt(9.81 * 0.3), 1e-12);
}

TEST(CaseReader, SlurryOpenBoundaryAndStructureErrorsNameTheKey) {
    // A Bingham fluid has n = 1; shear thinning needs mu_max (unbounded at rest).
    std::string e =
        error_of(minimal, {"sph.viscosity=\"bingham\"", "sph.consistency=1", "sph.yield_stress=10",
                           "sph.regularization=100", "sph.flow_index=0.5"});
    EXPECT_NE(e.find("key 'sph.flow_index'"), std::string::npos) << e;
    e = error_of(minimal, {"sph.viscosity=\"herschel_bulkley\"", "sph.consistency=1",
                           "sph.yield_stress=10", "sph.regularization=100", "sph.flow_index=0.5"});
    EXPECT_NE(e.find("missing required key 'sph.mu_max'"), std::string::npos) << e;
    const auto c = test::case_from_toml("bingham", minimal,
                                        {"sph.viscosity=\"bingham\"", "sph.consistency=2",
                                         "sph.yield_stress=10", "sph.regularization=100"});
    EXPECT_DOUBLE_EQ(std::get<models::BinghamViscosity>(c.sph.viscosity_model).mu_max,
                     2 + 10 * 100); // mu_p + tau_y m
    // An inlet buffer shorter than the kernel support; a hydrograph with a missing value.
    e = error_of(std::string(minimal) + R"(
[[inlet]]
name = "in"
min = [0.5, 0]
max = [0.52, 0.1]
discharge = 0.01
)");
    EXPECT_NE(e.find("key 'inlet.0.max'"), std::string::npos) << e;
    EXPECT_NE(e.find("kernel support"), std::string::npos) << e;
    e = error_of(std::string(minimal) + R"(
[[inlet]]
name = "in"
min = [0.5, 0]
max = [0.6, 0.1]
times = [0, 1]
discharge = [0.01]
)");
    EXPECT_NE(e.find("key 'inlet.0.discharge'"), std::string::npos) << e;
    // A slit dam in 2D; an unknown structure type.
    e = error_of(std::string(minimal) + R"(
[[structure]]
name = "dam"
type = "slit_dam"
position = 0.5
thickness = 0.05
height = 0.1
width = 0.3
slits = 1
slit_width = 0.05
)");
    EXPECT_NE(e.find("key 'structure.0.type'"), std::string::npos) << e;
    EXPECT_NE(e.find("3D"), std::string::npos) << e;
    e = error_of(std::string(minimal) + "[[structure]]\nname = \"x\"\ntype = \"weir\"\n");
    EXPECT_NE(e.find("unknown choice \"weir\""), std::string::npos) << e;
}

// Rock feeds: 3D only, the shape files must exist, the sphericity bound is a fraction.
TEST(CaseReader, RockFeedErrorsNameTheKey) {
    const std::string feed = R"(
[[material]]
name = "rock"
law = "hertz_mindlin"
density = 2650
youngs_modulus = 1e7
poisson = 0.3
restitution = 0.5
friction = 0.5
[[feed]]
name = "hopper"
material = "rock"
min = [0, 0]
max = [0.2, 0.2]
diameter = 0.02
discharge = 1e-4
rocks = ["no_such_rock.stl"]
)";
    std::string e = error_of(std::string(minimal) + feed);
    EXPECT_NE(e.find("'feed.0.rocks'"), std::string::npos) << e;
    EXPECT_NE(e.find("need dimensions = 3"), std::string::npos) << e;
    std::string three = minimal;
    three.replace(three.find("[-0.1, -0.1]"), 12, "[-0.1, -0.1, -0.1]");
    three.replace(three.find("[1.0, 1.0]"), 10, "[1.0, 1.0, 1.0]");
    three.replace(three.find("min = [0, 0]"), 12, "min = [0, 0, 0]");
    three.replace(three.find("max = [0.2, 0.2]"), 16, "max = [0.2, 0.2, 0.2]");
    std::string feed3 = feed;
    feed3.replace(feed3.find("min = [0, 0]"), 12, "min = [0, 0, 0.3]");
    feed3.replace(feed3.find("max = [0.2, 0.2]"), 16, "max = [0.2, 0.2, 0.5]");
    e = error_of("dimensions = 3\n" + three + feed3);
    EXPECT_NE(e.find("mesh file not found"), std::string::npos) << e;
    EXPECT_NE(e.find("no_such_rock.stl"), std::string::npos) << e;
    const std::string lib = std::string(DEBRISFLOW_SOURCE_DIR) + "/cases/shapes/rock_a.stl";
    feed3.replace(feed3.find("no_such_rock.stl"), 16, lib);
    e = error_of("dimensions = 3\n" + three + feed3 + "sphericity_tolerance = 15\n");
    EXPECT_NE(e.find("'feed.0.sphericity_tolerance'"), std::string::npos) << e;
    const auto c = test::case_from_toml("rock_feed_ok", "dimensions = 3\n" + three + feed3);
    ASSERT_EQ(c.rigid.feeds.size(), 1u);
    EXPECT_TRUE(c.dem.feeds.empty());
    EXPECT_TRUE(c.has_bodies());
    EXPECT_NEAR(c.rigid.feeds[0].sphericity_tolerance, 0.15, 1e-15);
}

// NaN, infinity and overflowing literals are rejected where they are read, in arrays too.
TEST(CaseReader, NonFiniteNumbersAreRejectedWithTheKey) {
    EXPECT_NE(error_of(minimal, {"sph.alpha=nan"}).find("key 'sph.alpha': must be a finite"),
              std::string::npos);
    // 1e999 is no TOML float (it overflows): --set takes it as a string, which is refused.
    EXPECT_NE(error_of(minimal, {"time.end=1e999"}).find("key 'time.end': expected a number"),
              std::string::npos);
    EXPECT_NE(error_of(minimal, {"fluid.0.max=[0.2, -inf]"})
                  .find("key 'fluid.0.max': every element must be a finite number"),
              std::string::npos);
    EXPECT_NE(error_of(minimal, {"domain.min=[-1e308, -0.1]", "domain.max=[1e308, 1]"})
                  .find("key 'domain.max': the extent in x overflows"),
              std::string::npos);
}

TEST(CaseReader, NamesAreFileSafe) {
    EXPECT_NE(error_of(minimal, {"fluid.0.name=\"a/b\""}).find("key 'fluid.0.name': a name may"),
              std::string::npos);
    EXPECT_NE(error_of(minimal, {"name=\"\""}).find("a name needs 1 to 64 characters, got 0"),
              std::string::npos);
    EXPECT_EQ(io::file_safe_name("my case (v2).toml"), "my_case__v2_.toml");
    EXPECT_EQ(io::file_safe_name(".hidden"), "_hidden");
    EXPECT_EQ(io::file_safe_name(std::string(100, 'x')).size(), 64u);
}

// A spec keeps where its blocks are, so that builders name file, line and key.
TEST(CaseReader, OriginsNameLineAndKey) {
    const auto c = test::case_from_toml("origin", minimal);
    ASSERT_EQ(c.fluids.size(), 1u);
    EXPECT_NE(c.fluids[0].origin.at("max").find(":13:7: key 'fluid.0.max'"), std::string::npos)
        << c.fluids[0].origin.at("max");
    EXPECT_NE(c.fluids[0].origin.block().find(": [fluid.0]"), std::string::npos);
    EXPECT_NE(c.domain_origin.at("max").find(":6:7: key 'domain.max'"), std::string::npos);
}

TEST(MemoryBudget, ParsesSizes) {
    EXPECT_DOUBLE_EQ(parse_bytes("4G"), 4.0 * (1L << 30));
    EXPECT_DOUBLE_EQ(parse_bytes("512MiB"), 512.0 * (1L << 20));
    EXPECT_DOUBLE_EQ(parse_bytes("2e9"), 2e9);
    EXPECT_THROW(parse_bytes("4Q"), InputError);
    EXPECT_THROW(parse_bytes("nan"), InputError);
    EXPECT_THROW(parse_bytes("1K"), InputError); // below 1 MiB
}

// The echoed case.toml writes shortest round-trip numbers and parses back to the same document
// for every shipped case.
TEST(CaseReader, EchoedCaseRoundTrips) {
    const auto c = test::case_from_toml("echo", minimal, {"time.end=0.1", "sph.c0=20.5"});
    EXPECT_NE(c.resolved_toml.find("end = 0.1\n"), std::string::npos) << c.resolved_toml;
    EXPECT_NE(c.resolved_toml.find("c0 = 20.5\n"), std::string::npos) << c.resolved_toml;
    EXPECT_EQ(c.resolved_toml.find("0000000"), std::string::npos) << c.resolved_toml;
    namespace fs = std::filesystem;
    int cases = 0;
    for (const auto& e : fs::recursive_directory_iterator(DEBRISFLOW_SOURCE_DIR "/cases")) {
        if (e.path().extension() != ".toml") continue;
        const toml::table doc = toml::parse_file(e.path().string());
        const toml::table again = toml::parse(io::echo_toml(doc));
        EXPECT_EQ(doc, again) << e.path();
        ++cases;
    }
    EXPECT_GT(cases, 20);
}
