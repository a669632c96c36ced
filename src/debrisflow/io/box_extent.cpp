#include "debrisflow/io/box_extent.hpp"
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::io {

std::string unresolvable_box(Vec3 lo, Vec3 hi, int dim) {
    for (int d = 0; d < 3; ++d) {
        if (dim == 2 && d == 1) continue;
        const Real a = std::fabs(lo[d]), b = std::fabs(hi[d]);
        if (!(a <= max_wall_coordinate && b <= max_wall_coordinate))
            return fmt::format("reaches {:.4g} m in {}, beyond the {:.0e} m any wall may reach",
                               a > b ? lo[d] : hi[d], "xyz"[d], max_wall_coordinate);
        const Real extent = hi[d] - lo[d];
        if (!(extent > Real(1e-9) * (1 + a + b)))
            return fmt::format("is {:.3g} m across in {} at {:.6g} m: too thin for its faces "
                               "to be resolved",
                               extent, "xyz"[d], lo[d]);
    }
    return {};
}

} // namespace debrisflow::io
