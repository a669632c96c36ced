#pragma once
// The probes' view of a resident backend's fluid (probes/fluid_reader.hpp): evaluated where the
// particles are, on the resident grid, with fluid_samples_k.hpp's rules; only the points go
// there and their few values, or the selected particles' rows, come back (issue #33), so no
// probe copies the particle arrays to the host.
#include "debrisflow/probes/fluid_reader.hpp"
#include <limits>
#include <variant>
#include <vector>

namespace debrisflow::sph {

template <class Space> class ResidentSph;

template <class Space> class ResidentFluidReader final : public probes::FluidReader {
    template <class T> using Buffer = typename Space::template Buffer<T>;

public:
    explicit ResidentFluidReader(const ResidentSph<Space>& sph) : sph_(sph) {}

    std::vector<probes::PointSample> samples(const std::vector<Vec3>& points) const override {
        return at_points<probes::ShepardSample, probes::PointSample>(points, samples_);
    }
    std::vector<Real> filled(const std::vector<Vec3>& points) const override {
        return at_points<probes::FilledFraction, Real>(points, fractions_);
    }
    Real front(int axis, Real sign) const override {
        const Real lowest = -std::numeric_limits<Real>::max();
        return Space::max_from(sph_.size(),
                               probes::FrontCoordinate{sph_.view(), axis, sign, lowest}, lowest);
    }
    Vec3 wall_load(int group) const override {
        const probes::WallParticleLoad load{sph_.view(), group};
        Vec3 f;
        for (int k = 0; k < 3; ++k)
            f[k] = Space::sum_of(sph_.size(), probes::WallLoadComponent{load, k});
        return f;
    }

    std::size_t bytes() const {
        return points_.bytes() + samples_.bytes() + fractions_.bytes() + flag_.bytes() +
               at_.bytes() + rows_.bytes();
    }

protected:
    // Stream compaction of the selected particles' rows (flags, their exclusive scan, a
    // gather); only the rows come back.
    std::vector<probes::ParticleRow> select(const probes::RowSelection& selection) const override {
        const Index n = sph_.size();
        flag_.resize(n);
        at_.resize(n);
        const auto pv = sph_.view();
        Space::for_each(n, probes::FlagSelected{pv, selection, flag_.data()});
        const Index m = Space::exclusive_scan(n, flag_.data(), at_.data());
        rows_.resize(m);
        Space::for_each(
            n, probes::GatherRows{pv, sph_.id_.data(), flag_.data(), at_.data(), rows_.data()});
        std::vector<probes::ParticleRow> rows(static_cast<std::size_t>(m));
        if (m > 0) rows_.download(rows.data());
        return rows;
    }

private:
    // f(x) at every point with the case's kernel, f = Sampler<Kernel>{particles, grid, kernel}.
    template <template <class> class Sampler, class Out>
    std::vector<Out> at_points(const std::vector<Vec3>& points, Buffer<Out>& out) const {
        const Index m = Index(points.size());
        points_.upload(points.data(), m);
        out.resize(m);
        std::visit(
            [&](const auto& kernel) {
                using K = std::decay_t<decltype(kernel)>;
                const Sampler<K> f{sph_.view(), sph_.grid_, kernel};
                Space::for_each(m,
                                probes::AtPoints<Sampler<K>, Out>{f, points_.data(), out.data()});
            },
            sph_.host_.models().kernel);
        std::vector<Out> values(points.size());
        out.download(values.data());
        return values;
    }

    const ResidentSph<Space>& sph_;
    mutable Buffer<Vec3> points_;
    mutable Buffer<probes::PointSample> samples_;
    mutable Buffer<Real> fractions_;
    mutable Buffer<Index> flag_, at_; // the rows' selection flags and positions
    mutable Buffer<probes::ParticleRow> rows_;
};

} // namespace debrisflow::sph
