#include "debrisflow/probes/runout_probe.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/probes/grain_reader.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace debrisflow::probes {

namespace {

// Disjoint sets with path halving and union by size.
struct Groups {
    std::vector<Index> parent, size;
    explicit Groups(Index n) : parent(std::size_t(n)), size(std::size_t(n), 1) {
        std::iota(parent.begin(), parent.end(), Index(0));
    }
    Index root(Index i) {
        while (parent[std::size_t(i)] != i) {
            parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
            i = parent[std::size_t(i)];
        }
        return i;
    }
    void join(Index a, Index b) {
        a = root(a), b = root(b);
        if (a == b) return;
        if (size[std::size_t(a)] < size[std::size_t(b)]) std::swap(a, b);
        parent[std::size_t(b)] = a;
        size[std::size_t(a)] += size[std::size_t(b)];
    }
};

// Cell of a point in a grid of spacing h, packed into one key (21 bits per axis, offset so
// that negative cells pack too; a deposit spans far fewer than 2^21 cells of a grain's size).
std::uint64_t cell_key(long cx, long cy, long cz) {
    constexpr long offset = 1L << 20;
    constexpr std::uint64_t mask = (1ULL << 21) - 1;
    return ((std::uint64_t(cx + offset) & mask) << 42) |
           ((std::uint64_t(cy + offset) & mask) << 21) | (std::uint64_t(cz + offset) & mask);
}

} // namespace

Runout measure_runout(std::span<const Vec3> pos, std::span<const Real> radius,
                      std::span<const Real> mass, std::span<const std::int32_t> clump, int axis,
                      int sign, Real bed, Real gap) {
    Runout out;
    const Index n = Index(pos.size());
    if (n == 0) return out;
    const auto edge = [&](Index i) {
        return Real(sign) * pos[std::size_t(i)][axis] + radius[std::size_t(i)];
    };

    // Link grains whose surfaces are closer than gap x the smaller diameter: a cell grid of
    // the largest link distance, each grain against its own and the neighbouring cells.
    const Real r_max = *std::max_element(radius.begin(), radius.end());
    const Real h = 2 * r_max * (1 + gap);
    const auto cell = [&](Real c) { return long(std::floor(c / h)); };
    std::unordered_map<std::uint64_t, std::vector<Index>> cells;
    cells.reserve(std::size_t(n));
    for (Index i = 0; i < n; ++i) {
        const Vec3 p = pos[std::size_t(i)];
        cells[cell_key(cell(p.x), cell(p.y), cell(p.z))].push_back(i);
    }
    Groups groups(n);
    for (Index i = 0; i < n; ++i) {
        const Vec3 p = pos[std::size_t(i)];
        const Real ri = radius[std::size_t(i)];
        const long cx = cell(p.x), cy = cell(p.y), cz = cell(p.z);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (long dz = -1; dz <= 1; ++dz) {
                    const auto it = cells.find(cell_key(cx + dx, cy + dy, cz + dz));
                    if (it == cells.end()) continue;
                    for (const Index j : it->second) {
                        if (j <= i) continue;
                        const Real rj = radius[std::size_t(j)];
                        const Real reach = ri + rj + gap * 2 * std::min(ri, rj);
                        const Vec3 d = pos[std::size_t(j)] - p;
                        if (dot(d, d) <= reach * reach) groups.join(i, j);
                    }
                }
    }
    if (!clump.empty()) { // the members of a clump move as one
        std::unordered_map<std::int32_t, Index> first;
        for (Index i = 0; i < n; ++i) {
            const std::int32_t c = clump[std::size_t(i)];
            if (c < 0) continue;
            const auto [it, added] = first.emplace(c, i);
            if (!added) groups.join(i, it->second);
        }
    }

    // The deposit: the group of largest mass.
    std::vector<Real> group_mass(std::size_t(n), 0);
    for (Index i = 0; i < n; ++i) group_mass[std::size_t(groups.root(i))] += mass[std::size_t(i)];
    const Index deposit =
        Index(std::max_element(group_mass.begin(), group_mass.end()) - group_mass.begin());

    out.front = out.front_max = -std::numeric_limits<Real>::max();
    out.height = -std::numeric_limits<Real>::max();
    std::vector<std::pair<Real, Real>> edges; // (edge, mass), for the mass percentile
    edges.reserve(std::size_t(n));
    Real total = 0;
    for (Index i = 0; i < n; ++i) {
        const std::size_t k = std::size_t(i);
        const Real e = edge(i);
        edges.emplace_back(e, mass[k]);
        total += mass[k];
        out.front_max = std::max(out.front_max, e);
        if (groups.root(i) == deposit) {
            out.front = std::max(out.front, e);
            out.height = std::max(out.height, pos[k].z + radius[k] - bed);
        } else {
            ++out.detached;
            out.detached_mass += mass[k];
        }
    }
    std::sort(edges.begin(), edges.end());
    Real behind = 0;
    out.front_95 = edges.back().first;
    for (const auto& [e, m] : edges) {
        behind += m;
        if (behind >= Real(0.95) * total) {
            out.front_95 = e;
            break;
        }
    }
    // back to coordinates (the edges were taken along sign x axis)
    out.front *= Real(sign);
    out.front_95 *= Real(sign);
    out.front_max *= Real(sign);
    return out;
}

std::unique_ptr<Probe> RunoutProbe::from_config(const ProbeSetup& s) {
    s.require(s.c.has_dem, "[[grains]]");
    const std::string a =
        s.t.choice("axis", {"x", "y", "z", "+x", "+y", "+z", "-x", "-y", "-z"}, "x");
    const int axis = a.back() == 'x' ? 0 : (a.back() == 'y' ? 1 : 2);
    if (s.c.dim == 2 && axis == 1) s.t.fail("axis", "2D cases flow in the x-z plane");
    const Real gap = s.t.real("gap", 0.05);
    if (!(gap >= 0 && gap <= 1))
        s.t.fail("gap", "must lie in [0, 1] (a fraction of the smaller grain's diameter)");
    return std::make_unique<RunoutProbe>(s.name(), s.every(), axis, a.front() == '-' ? -1 : 1,
                                         s.bed(), gap);
}

// Every grain's row, in id order, from where the grains are (GrainReader::rows).
std::vector<Real> RunoutProbe::sample(Real, const ProbeContext& ctx) {
    const Real far = std::numeric_limits<Real>::max();
    const std::vector<GrainRow> rows = ctx.grains->rows({{-far, -far, -far}, {far, far, far}});
    if (rows.empty()) return {0, 0, 0, 0, 0, 0};
    std::vector<Vec3> pos;
    std::vector<Real> radius, mass;
    std::vector<std::int32_t> clump;
    bool clumps = false;
    for (const GrainRow& r : rows) {
        pos.push_back(r.pos), radius.push_back(r.radius), mass.push_back(r.mass);
        clump.push_back(r.clump);
        clumps = clumps || r.clump >= 0;
    }
    if (!clumps) clump.clear();
    const Runout r = measure_runout(pos, radius, mass, clump, axis_, sign_, bed_, gap_);
    return {r.front, r.front_95, r.front_max, r.height, Real(r.detached), r.detached_mass};
}

} // namespace debrisflow::probes
