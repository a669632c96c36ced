#include "debrisflow/scenario/overlap_grid.hpp"

#include <algorithm>
#include <cmath>

namespace debrisflow::scenario {

OverlapGrid::OverlapGrid(Real r_min, Real r_max, int dim) : dim_(dim) {
    Real r = r_min;
    do {
        Level l;
        l.r_max = r;
        l.cell = 2 * r;
        levels_.push_back(std::move(l));
        r *= 2;
    } while (levels_.back().r_max < r_max && levels_.size() < 64);
}

long OverlapGrid::key(long i, long j, long k) {
    return (i * 73856093L) ^ (j * 19349663L) ^ (k * 83492791L);
}

bool OverlapGrid::overlaps_any(Vec3 p, Real r, const std::vector<int>& ids) const {
    for (int id : ids) {
        const Vec3 s = p - centre_[std::size_t(id)];
        const Real reach = r + radius_[std::size_t(id)];
        if (dot(s, s) < reach * reach) return true;
    }
    return false;
}

bool OverlapGrid::overlaps(Vec3 p, Real r) const {
    for (const Level& l : levels_) {
        if (l.members.empty()) continue;
        // cells within r + (largest radius held) of p: k cells either side; a sphere much
        // larger than the level's cells scans the level's members instead
        const double kd = std::ceil(double(r + l.r_held) / double(l.cell));
        const double span = 2 * kd + 1;
        if (span * span * (dim_ == 3 ? span : 1.0) >= double(l.members.size())) {
            if (overlaps_any(p, r, l.members)) return true;
            continue;
        }
        const long i0 = long(std::floor(p.x / l.cell)), j0 = long(std::floor(p.y / l.cell)),
                   k0 = long(std::floor(p.z / l.cell));
        const long k = long(kd), ky = dim_ == 3 ? k : 0;
        for (long dk = -k; dk <= k; ++dk)
            for (long dj = -ky; dj <= ky; ++dj)
                for (long di = -k; di <= k; ++di) {
                    const auto it = l.cells.find(key(i0 + di, j0 + dj, k0 + dk));
                    if (it != l.cells.end() && overlaps_any(p, r, it->second)) return true;
                }
    }
    return false;
}

void OverlapGrid::add(Vec3 p, Real r) {
    const int id = int(centre_.size());
    centre_.push_back(p);
    radius_.push_back(r);
    std::size_t L = 0;
    while (L + 1 < levels_.size() && levels_[L].r_max < r) ++L;
    Level& l = levels_[L];
    l.members.push_back(id);
    l.r_held = std::max(l.r_held, r);
    l.cells[key(long(std::floor(p.x / l.cell)), long(std::floor(p.y / l.cell)),
                long(std::floor(p.z / l.cell)))]
        .push_back(id);
}

} // namespace debrisflow::scenario
