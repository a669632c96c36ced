// exec::exclusive_scan (the step of stream compaction and counting sorts) against a serial
// prefix sum, and the particle set's compaction and permutation built on it: every array,
// the SPS stress (6 per particle) and the ids follow, in order.
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <gtest/gtest.h>
#include <vector>

using namespace debrisflow;

TEST(ExecScan, ExclusivePrefixSumOnEveryThreadCount) {
    const int before = exec::max_threads();
    for (int threads : {1, 2, 3}) {
        exec::set_threads(threads);
        for (Index n : {0, 1, 2, 7, 1000, 100003}) {
            const auto value = [](Index i) { return long((i * 7919) % 5); };
            std::vector<long> out(std::size_t(n), -1);
            const long total = exec::exclusive_scan(n, value, out.data());
            long sum = 0;
            for (Index i = 0; i < n; ++i) {
                ASSERT_EQ(out[std::size_t(i)], sum) << "n " << n << ", i " << i;
                sum += value(i);
            }
            EXPECT_EQ(total, sum) << "threads " << threads << ", n " << n;
        }
    }
    exec::set_threads(before);
}

namespace {
particles::ParticleSet numbered(Index n) {
    particles::ParticleSet s;
    for (Index i = 0; i < n; ++i)
        s.add({Real(i), 2 * Real(i), 3 * Real(i)}, {Real(-i), 0, 1}, 1000 + Real(i), 1,
              i % 3 ? particles::Kind::fluid : particles::Kind::boundary, std::int16_t(i % 4));
    s.sps_tau.resize(6 * std::size_t(n));
    for (std::size_t k = 0; k < s.sps_tau.size(); ++k) s.sps_tau[k] = Real(k);
    return s;
}
} // namespace

TEST(ExecScan, ParticleSetCompactKeepsOrderAndEveryArray) {
    const int before = exec::max_threads();
    exec::set_threads(2);
    const Index n = 20001;
    particles::ParticleSet s = numbered(n);
    std::vector<std::uint8_t> keep(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) keep[std::size_t(i)] = (i % 7 == 2 || i % 5 == 0) ? 0 : 1;
    s.compact(keep);
    Index w = 0;
    for (Index i = 0; i < n; ++i) {
        if (!keep[std::size_t(i)]) continue;
        const auto k = std::size_t(w);
        ASSERT_EQ(s.id[k], ParticleId(i));
        EXPECT_EQ(s.x[k], Real(i));
        EXPECT_EQ(s.z[k], 3 * Real(i));
        EXPECT_EQ(s.vx[k], Real(-i));
        EXPECT_EQ(s.rho[k], 1000 + Real(i));
        EXPECT_EQ(s.rho_old[k], 1000 + Real(i));
        EXPECT_EQ(s.group[k], std::int16_t(i % 4));
        for (std::size_t c = 0; c < 6; ++c) EXPECT_EQ(s.sps_tau[6 * k + c], Real(6 * i + c));
        ++w;
    }
    EXPECT_EQ(s.size(), w);
    EXPECT_EQ(s.sps_tau.size(), 6 * std::size_t(w));
    exec::set_threads(before);
}

TEST(ExecScan, ParticleSetPermuteMovesEveryArray) {
    const int before = exec::max_threads();
    exec::set_threads(2);
    const Index n = 10007;
    particles::ParticleSet s = numbered(n);
    s.drop_previous_state(); // a symplectic run: the Verlet arrays stay empty
    std::vector<Index> perm(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) perm[std::size_t(i)] = (i * 4099) % n; // 4099 prime to n
    s.permute(perm);
    for (Index i = 0; i < n; ++i) {
        const auto k = std::size_t(i);
        const Index from = perm[k];
        ASSERT_EQ(s.id[k], ParticleId(from));
        EXPECT_EQ(s.y[k], 2 * Real(from));
        EXPECT_EQ(s.kind[k], from % 3 ? 0 : 1);
        for (std::size_t c = 0; c < 6; ++c) EXPECT_EQ(s.sps_tau[6 * k + c], Real(6 * from + c));
    }
    EXPECT_TRUE(s.vx_old.empty());
    exec::set_threads(before);
}
