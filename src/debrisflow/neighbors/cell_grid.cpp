#include "debrisflow/neighbors/cell_grid.hpp"
#include "debrisflow/core/error.hpp"
#include <cmath>
#include <string>

namespace debrisflow::neighbors {

void CellGrid::configure(Vec3 lo, Vec3 hi, Real radius, int dim, std::array<bool, 3> periodic) {
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
        nc_[d] = std::max(1, int(std::floor(len / radius)));
        if (periodic[d] && nc_[d] < 3)
            throw InputError("periodic direction " + std::string(1, "xyz"[d]) +
                             " is shorter than three kernel supports; enlarge the domain");
        view_.inv_cell[d] = Real(nc_[d]) / len;
    }
    for (int d = 0; d < 3; ++d) view_.nc[d] = nc_[d];
    start_.assign(std::size_t(cell_count()) + 1, 0);
}

void CellGrid::build(const Real* x, const Real* y, const Real* z, Index n, int stride) {
    cell_of_.resize(n);
    order_.resize(n);
    const GridView g = view_;
    const int n0 = nc_[0], n1 = nc_[1];
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        const std::size_t k = std::size_t(i) * std::size_t(stride);
        cell_of_[i] =
            g.cell_coord(x[k], 0) + n0 * (g.cell_coord(y[k], 1) + n1 * g.cell_coord(z[k], 2));
    }
    const int nc = cell_count();
    count_.assign(std::size_t(nc) + 1, 0);
    for (Index i = 0; i < n; ++i) ++count_[cell_of_[i] + 1];
    for (int c = 0; c < nc; ++c) count_[c + 1] += count_[c];
    start_.assign(count_.begin(), count_.end());
    for (Index i = 0; i < n; ++i) order_[count_[cell_of_[i]]++] = i;
    view_.start = start_.data();
    view_.order = order_.data();
}

GridView CellGrid::view() const {
    return view_;
}

} // namespace debrisflow::neighbors
