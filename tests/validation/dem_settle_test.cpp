// Settling a random packing to PFC's equilibrium ratio (mean unbalanced force / mean contact
// force < 0.01, Itasca PFC's usual static criterion) with tangential springs as stiff as the
// normal ones (k_t = k_n) and the coarse dem.safety = 0.1 a user reported: discs (2D) and
// spheres (3D) of 4-6 mm in a box. Before the automatic step covered the tangential-rotational
// mode (sqrt(3) times the normal frequency for discs, sqrt(3.5) for spheres), the disc packing
// kept a kinetic-energy floor and stalled at a ratio of about 0.16 after 3 s.
#include "run_case.hpp"
#include <cstdio>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {

std::string packing_case(int dim, int count, bool dimers, double restitution) {
    const bool plane = dim == 2;
    std::string s = "name = \"settle_" + std::to_string(dim) +
                    "d\"\ndimensions = " + std::to_string(dim) + "\n";
    s += R"(
[time]
end = 1e-4
[output]
vtk = false
[dem]
safety = 0.1
settle = true
settle_ratio = 0.01
settle_max_time = 2
)";
    if (plane) s += "thickness = 0.005\n";
    s += plane ? "[domain]\nmin = [-0.01, 0, -0.01]\nmax = [0.11, 0, 0.4]\n"
               : "[domain]\nmin = [-0.01, -0.01, -0.01]\nmax = [0.07, 0.07, 0.4]\n";
    s += R"(
[[material]]
name = "glass"
density = 2500
kn = 1e5
kt = 1e5
friction = 0.5
)";
    s += "restitution = " + std::to_string(restitution) + "\n";
    s += R"(
[[wall]]
name = "floor"
shape = "plane"
material = "glass"
point = [0, 0, 0]
normal = [0, 0, 1]
)";
    const char* planes[][2] = {{"[0, 0, 0]", "[1, 0, 0]"},
                               {plane ? "[0.1, 0, 0]" : "[0.06, 0, 0]", "[-1, 0, 0]"},
                               {"[0, 0, 0]", "[0, 1, 0]"},
                               {"[0, 0.06, 0]", "[0, -1, 0]"}};
    for (int k = 0; k < (plane ? 2 : 4); ++k)
        s += "[[wall]]\nname = \"side" + std::to_string(k) +
             "\"\nshape = \"plane\"\nmaterial = \"glass\"\npoint = " + planes[k][0] +
             "\nnormal = " + planes[k][1] + "\n";
    s += "[[grains]]\nname = \"g\"\nmaterial = \"glass\"\ncount = " + std::to_string(count) +
         "\nseed = 3\n";
    s += "size = {distribution = \"lognormal\", d50 = 0.005, sigma = 0.1, min = 0.004, max = "
         "0.006}\n";
    if (dimers) s += "clump = [[-1, 0, 0, 1], [1, 0, 0, 1]]\n";
    s += plane ? "region = {shape = \"box\", min = [0, 0, 0], max = [0.1, 0, 0.3]}\n"
               : "region = {shape = \"box\", min = [0, 0, 0], max = [0.06, 0.06, 0.3]}\n";
    return s;
}

} // namespace

// The run settles before t = 0 (it would stop with "did not settle within
// dem.settle_max_time" otherwise) and the packing is still in equilibrium after the short run:
// ratio < 0.01, the criterion itself (no tolerance).
TEST(DemSettle, DiscsAndSpheresWithStiffTangentialSpringsReachTheEquilibriumRatio) {
    struct Packing {
        int dim, count;
        bool dimers;
        double restitution;
    };
    // e = 0.1: its tangential dashpot (zeta 1.02 for discs) limits the step; at the spring-only
    // step the discs kept spinning and stalled at a ratio of 0.12 (dem/critical_dt.cpp)
    for (const auto& [dim, count, dimers, e] :
         {Packing{2, 500, false, 0.5}, Packing{3, 500, false, 0.5}, Packing{2, 250, true, 0.5},
          Packing{2, 500, false, 0.1}, Packing{3, 500, false, 0.1}}) {
        app::Simulation sim(test::case_from_toml("settle", packing_case(dim, count, dimers, e)));
        sim.grains().measure_contact_force(true); // for the ratio after the run
        app::RunOptions opt;
        opt.quiet = true;
        ASSERT_NO_THROW(sim.run(opt)) << dim << "D";
        const Real ratio = sim.grains().unbalanced_ratio();
        std::printf("%dD, %d %s, e = %g: dt %.3g s (%s); unbalanced ratio after settling %.4f\n",
                    dim, count, dimers ? "two-disc clumps" : "grains", e, sim.grains().dt(),
                    sim.grains().automatic_dt().limiter.c_str(), ratio);
        EXPECT_LT(ratio, 0.01) << dim << "D, e = " << e;
        EXPECT_NE(sim.grains().automatic_dt().limiter.find("tangential-rotational"),
                  std::string::npos);
    }
}
