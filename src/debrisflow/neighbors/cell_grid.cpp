#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/counting_sort.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/neighbors/cell_keys_k.hpp"
#include <cmath>
#include <string>

namespace debrisflow::neighbors {

void CellGrid::configure(Vec3 lo, Vec3 hi, Real radius, int dim, std::array<bool, 3> periodic) {
    // Cells larger than the search radius find the same pairs (more candidates per cell), so
    // a domain that is huge against the radius gets at most max_cells cells instead of
    // allocating (or overflowing) one cell per radius.
    constexpr double max_cells = 1 << 26;
    double cells = 1;
    for (int d = 0; d < 3; ++d)
        if (!(dim == 2 && d == 1))
            cells *= std::max(1.0, std::floor(double(hi[d] - lo[d]) / radius));
    if (!std::isfinite(cells))
        throw InputError("the neighbour grid's extent is not finite; check domain.min/max");
    const bool any_periodic = periodic[0] || periodic[1] || periodic[2];
    const Real cell =
        cells > max_cells && !any_periodic
            ? radius * Real(std::pow(cells / max_cells, 1.0 / (dim == 3 ? 3 : 2)) * 1.001)
            : radius;
    view_ = GridView{};
    view_.radius2 = radius * radius;
    for (int d = 0; d < 3; ++d) {
        const Real len = hi[d] - lo[d];
        view_.lo[d] = lo[d];
        view_.length[d] = len;
        view_.periodic[d] = periodic[d] ? 1 : 0;
        if (dim == 2 && d == 1) {
            nc_[d] = 1;
            view_.inv_cell[d] = 0;
            view_.periodic[d] = 0;
            continue;
        }
        nc_[d] = int(std::max(1.0, std::min(double(max_cells), std::floor(double(len / cell)))));
        if (periodic[d] && nc_[d] < 3)
            throw InputError("periodic direction " + std::string(1, "xyz"[d]) +
                             " is shorter than three kernel supports; enlarge the domain");
        view_.inv_cell[d] = Real(nc_[d]) / len;
    }
    for (int d = 0; d < 3; ++d) view_.nc[d] = nc_[d];
    if (double(nc_[0]) * nc_[1] * nc_[2] > 2 * max_cells)
        throw InputError("a periodic domain needs more than 1.3e8 neighbour cells; enlarge dp "
                         "or shorten the periodic directions");
    start_.assign(std::size_t(cell_count()) + 1, 0);
}

void CellGrid::build(const Real* x, const Real* y, const Real* z, Index n, int stride,
                     const std::uint8_t* cls) {
    cell_of_.resize(n);
    order_.resize(n);
    const int classes = cls ? 2 : 1;
    exec::for_each(n, CellKeys{view_, x, y, z, stride, cls, cell_of_.data()});
    // Counting sort on the key (cell, or cell and class): stable, so a cell lists its
    // particles in index order.
    const int nk = cell_count() * classes;
    exec::counting_sort(cell_of_.data(), n, nk, order_.data(), start_, count_);
    view_.start = start_.data();
    view_.order = order_.data();
    view_.classes = classes;
}

bool CellGrid::in_order() const {
    for (std::size_t k = 0; k < order_.size(); ++k)
        if (order_[k] != Index(k)) return false;
    return true;
}

GridView CellGrid::view() const {
    return view_;
}

} // namespace debrisflow::neighbors
