#include "debrisflow/scenario/lattice.hpp"
#include "debrisflow/scenario/resource_estimate.hpp"
#include <cmath>
#include <unordered_map>

namespace debrisflow::scenario {

std::vector<Vec3> lattice(Vec3 lo, Vec3 hi, Vec3 origin, Real dp, int dim,
                          const std::function<bool(Vec3)>& keep, const std::string& what) {
    require_lattice_within_budget(lo, hi, dp, dim, what);
    std::vector<Vec3> out;
    long a[3], b[3];
    for (int d = 0; d < 3; ++d) {
        a[d] = long(std::ceil((lo[d] - origin[d]) / dp - 0.5 - 1e-9));
        b[d] = long(std::floor((hi[d] - origin[d]) / dp - 0.5 + 1e-9));
    }
    if (dim == 2) a[1] = b[1] = 0;
    for (long k = a[2]; k <= b[2]; ++k)
        for (long j = a[1]; j <= b[1]; ++j)
            for (long i = a[0]; i <= b[0]; ++i) {
                Vec3 p{origin.x + (i + 0.5) * dp, dim == 2 ? 0 : origin.y + (j + 0.5) * dp,
                       origin.z + (k + 0.5) * dp};
                if (keep(p)) out.push_back(p);
            }
    return out;
}

std::vector<Vec3> tank_walls(Vec3 lo, Vec3 hi, Real dp, int dim, int layers, bool closed_top,
                             const std::string& what) {
    const Real skin = layers * dp;
    require_lattice_within_budget(lo - Vec3{skin, skin, skin}, hi + Vec3{skin, skin, skin}, dp, dim,
                                  what);
    std::vector<Real> axis[3];
    std::vector<char> is_wall[3];
    for (int d = 0; d < 3; ++d) {
        if (dim == 2 && d == 1) {
            axis[d] = {0};
            is_wall[d] = {0};
            continue;
        }
        for (int k = layers - 1; k >= 0; --k) {
            axis[d].push_back(lo[d] - (k + 0.5) * dp);
            is_wall[d].push_back(1);
        }
        const long n = std::lround((hi[d] - lo[d]) / dp);
        for (long i = 0; i < n; ++i) {
            axis[d].push_back(lo[d] + (i + 0.5) * dp);
            is_wall[d].push_back(0);
        }
        if (d != 2 || closed_top)
            for (int k = 0; k < layers; ++k) {
                axis[d].push_back(lo[d] + (n + k + 0.5) * dp);
                is_wall[d].push_back(1);
            }
    }
    std::vector<Vec3> out;
    for (std::size_t k = 0; k < axis[2].size(); ++k)
        for (std::size_t j = 0; j < axis[1].size(); ++j)
            for (std::size_t i = 0; i < axis[0].size(); ++i)
                if (is_wall[0][i] || is_wall[1][j] || is_wall[2][k])
                    out.push_back({axis[0][i], axis[1][j], axis[2][k]});
    return out;
}

std::vector<Vec3> remove_near(const std::vector<Vec3>& pts, const std::vector<Vec3>& obstacles,
                              Real min_gap) {
    auto key = [&](Vec3 p, int dx, int dy, int dz) {
        const long i = long(std::floor(p.x / min_gap)) + dx;
        const long j = long(std::floor(p.y / min_gap)) + dy;
        const long k = long(std::floor(p.z / min_gap)) + dz;
        return (i * 73856093L) ^ (j * 19349663L) ^ (k * 83492791L);
    };
    std::unordered_multimap<long, Vec3> hash;
    hash.reserve(obstacles.size());
    for (const Vec3& o : obstacles) hash.emplace(key(o, 0, 0, 0), o);
    std::vector<Vec3> out;
    out.reserve(pts.size());
    const Real g2 = min_gap * min_gap;
    for (const Vec3& p : pts) {
        bool near = false;
        for (int dz = -1; dz <= 1 && !near; ++dz)
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    auto [a, b] = hash.equal_range(key(p, dx, dy, dz));
                    for (auto it = a; it != b; ++it) {
                        const Vec3 r = it->second - p;
                        if (dot(r, r) < g2) {
                            near = true;
                            break;
                        }
                    }
                }
        if (!near) out.push_back(p);
    }
    return out;
}

} // namespace debrisflow::scenario
