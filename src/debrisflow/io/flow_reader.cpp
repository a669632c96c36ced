#include "debrisflow/io/flow_reader.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::io {

namespace {
// Box `min`-`max` of a table; in 2D the y extent is the unit width.
void read_box(const ConfigTable& t, int dim, Vec3& lo, Vec3& hi) {
    lo = t.vec3("min", dim);
    hi = t.vec3("max", dim);
    if (dim == 2) lo.y = 0, hi.y = 0;
    for (int k = 0; k < 3; ++k)
        if (!(dim == 2 && k == 1) && !(hi[k] > lo[k]))
            t.fail("max", fmt::format("must exceed min in {}", "xyz"[k]));
}
} // namespace

void read_inlets(const ConfigTable& root, CaseSpec& c) {
    for (const auto& t : root.tables("inlet")) {
        InletSpec in;
        in.origin = t.origin();
        in.name = t.name("name");
        read_box(t, c.dim, in.min, in.max);
        const std::string dir = t.choice("direction", {"+x", "-x", "+y", "-y", "+z", "-z"}, "+x");
        in.sign = dir[0] == '+' ? 1 : -1;
        in.axis = dir[1] - 'x';
        if (c.dim == 2 && in.axis == 1) t.fail("direction", "2D cases flow in the x-z plane");
        if (t.has("times")) {
            in.times = t.reals("times");
            in.discharge = t.reals("discharge");
            if (in.times.size() != in.discharge.size() || in.times.empty())
                t.fail("discharge", "needs one value per entry of 'times' (a hydrograph)");
            for (std::size_t k = 1; k < in.times.size(); ++k)
                if (!(in.times[k] > in.times[k - 1])) t.fail("times", "must increase");
        } else {
            in.discharge = {t.real("discharge")};
            in.times = {0};
        }
        for (Real q : in.discharge)
            if (q < 0) t.fail("discharge", "must be >= 0 [m^3/s] (2D: m^2/s)");
        // The buffer must hold at least a kernel support of fluid along the flow.
        const Real length = in.max[in.axis] - in.min[in.axis];
        if (length < 2 * c.sph.h - 1e-12)
            t.fail("max", fmt::format("the buffer is {:.4g} m long along the flow; it must be at "
                                      "least the kernel support 2h = {:.4g} m",
                                      length, 2 * c.sph.h));
        in.every = t.positive("every", 0.01);
        t.finish();
        FluidSpec f;
        f.origin = t.origin();
        f.velocity[in.axis] = in.sign * in.discharge.front() / in.area(c.dim);
        f.name = in.name;
        f.shape.type = "box";
        f.shape.min = in.min;
        f.shape.max = in.max;
        f.hydrostatic = true;
        in.fluid = c.fluids.size();
        c.fluids.push_back(f);
        c.inlets.push_back(in);
    }
}

void read_outlets(const ConfigTable& root, CaseSpec& c) {
    for (const auto& t : root.tables("outlet")) {
        OutletSpec out;
        out.origin = t.origin();
        out.name = t.name("name");
        read_box(t, c.dim, out.min, out.max);
        if (c.dim == 2) out.min.y = -1, out.max.y = 1;
        out.every = t.positive("every", 0.01);
        t.finish();
        c.outlets.push_back(out);
    }
}

} // namespace debrisflow::io
