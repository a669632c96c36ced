#include "debrisflow/dem/wall_bins.hpp"
#include <algorithm>
#include <cmath>

namespace debrisflow::dem {

void WallBins::build(const std::vector<PrimitiveBounds>& bounds, Real reach, int dim) {
    view_ = WallBinsView{};
    start_.clear();
    items_.clear();
    always_.clear();
    const Index n = Index(bounds.size());
    if (n < min_primitives) return;
    // The grid's box: the union of the bounded primitives' boxes widened by the reach.
    Vec3 lo{}, hi{};
    std::vector<Real> sides; // largest side of each widened box
    for (const PrimitiveBounds& b : bounds) {
        if (!b.bounded) continue;
        Real side = 0;
        for (int d = 0; d < 3; ++d) {
            if (dim == 2 && d == 1) continue;
            const Real l = b.lo[d] - reach, h = b.hi[d] + reach;
            lo[d] = sides.empty() ? l : std::min(lo[d], l);
            hi[d] = sides.empty() ? h : std::max(hi[d], h);
            side = std::max(side, h - l);
        }
        sides.push_back(side);
    }
    if (sides.empty()) return;
    const Index binned = Index(sides.size());
    // Cells about the size of the median widened face (most faces then lie in 1-2 cells per
    // direction; the few much larger ones, a flume's bed beside its baffles, stay out of the
    // bins), coarsened until there are at most eight per face.
    std::nth_element(sides.begin(), sides.begin() + sides.size() / 2, sides.end());
    Real edge = std::max(sides[sides.size() / 2], Real(1e-12));
    const auto cells_along = [&](int d) {
        if (dim == 2 && d == 1) return 1.0;
        return std::max(1.0, std::floor(double(hi[d] - lo[d]) / double(edge)));
    };
    while (cells_along(0) * cells_along(1) * cells_along(2) > 8.0 * double(binned) + 64)
        edge *= Real(1.26);
    for (int d = 0; d < 3; ++d) {
        view_.nc[d] = int(cells_along(d));
        view_.lo[d] = lo[d];
        const Real len = hi[d] - lo[d];
        view_.inv_cell[d] = view_.nc[d] > 1 && len > 0 ? Real(view_.nc[d]) / len : 0;
    }
    const Index cells = Index(view_.nc[0]) * view_.nc[1] * view_.nc[2];
    // The cells a widened box covers (the same cell function as the queries: monotone, so a
    // point inside the box falls in one of them); a face over too many stays out of the bins.
    struct Span {
        int c0[3], c1[3];
        long count;
    };
    const auto span_of = [&](const PrimitiveBounds& b) {
        Span s{};
        s.count = 1;
        for (int d = 0; d < 3; ++d) {
            s.c0[d] = view_.coord(b.lo[d] - reach, d);
            s.c1[d] = view_.coord(b.hi[d] + reach, d);
            s.count *= s.c1[d] - s.c0[d] + 1;
        }
        return s;
    };
    const auto each_cell = [&](const Span& s, auto&& f) {
        for (int z = s.c0[2]; z <= s.c1[2]; ++z)
            for (int y = s.c0[1]; y <= s.c1[1]; ++y)
                for (int x = s.c0[0]; x <= s.c1[0]; ++x)
                    f(Index(x + view_.nc[0] * (y + view_.nc[1] * z)));
    };
    start_.assign(std::size_t(cells) + 1, 0);
    for (Index a = 0; a < n; ++a) {
        const PrimitiveBounds& b = bounds[std::size_t(a)];
        if (!b.bounded) continue;
        const Span s = span_of(b);
        if (s.count > max_cells_per_face) continue;
        each_cell(s, [&](Index c) { ++start_[std::size_t(c) + 1]; });
    }
    for (Index c = 0; c < cells; ++c) start_[std::size_t(c) + 1] += start_[std::size_t(c)];
    items_.resize(std::size_t(start_.back()));
    std::vector<Index> next(start_.begin(), start_.end() - 1);
    for (Index a = 0; a < n; ++a) { // ascending: each cell's list ascends
        const PrimitiveBounds& b = bounds[std::size_t(a)];
        const Span s = b.bounded ? span_of(b) : Span{};
        if (!b.bounded || s.count > max_cells_per_face) {
            always_.push_back(a);
            continue;
        }
        each_cell(s, [&](Index c) { items_[std::size_t(next[std::size_t(c)]++)] = a; });
    }
    view_.binned = true;
}

WallBinsView WallBins::view() const {
    WallBinsView v = view_;
    if (!v.binned) return v;
    v.start = start_.data();
    v.items = items_.data();
    v.always = always_.data();
    v.always_count = Index(always_.size());
    return v;
}

} // namespace debrisflow::dem
