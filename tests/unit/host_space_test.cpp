// The primitives a resident loop is written against (exec/host_space.hpp; CudaSpace offers the
// same calls on a device): the stable sort by key, the cell starts found by binary search, the
// scan of keep flags and the reductions, against serial references.
#include "debrisflow/exec/host_space.hpp"
#include "debrisflow/sph/resident_steps_k.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <numeric>
#include <random>

using namespace debrisflow;
using exec::HostSpace;

TEST(HostSpace, SortIsStableAndStartsBoundEachKey) {
    std::mt19937 rng(7);
    const Index n = 10007, key_count = 97;
    std::vector<Index> keys(n);
    for (auto& k : keys) k = Index(rng() % key_count);
    std::vector<Index> order(n), expected(n);
    HostSpace::Sorter sorter;
    sorter.sort(keys.data(), n, key_count, order.data());
    std::iota(expected.begin(), expected.end(), 0);
    std::stable_sort(expected.begin(), expected.end(),
                     [&](Index a, Index b) { return keys[a] < keys[b]; });
    EXPECT_EQ(order, expected);
    std::vector<Index> start(key_count + 1);
    HostSpace::for_each(key_count + 1, sph::CellStarts{keys.data(), order.data(), n, start.data()});
    for (Index c = 0; c < key_count; ++c) {
        EXPECT_EQ(start[c + 1] - start[c], std::count(keys.begin(), keys.end(), c)) << c;
        for (Index k = start[c]; k < start[c + 1]; ++k) EXPECT_EQ(keys[order[k]], c);
    }
    EXPECT_EQ(start[key_count], n);
}

TEST(HostSpace, ScanOfKeepFlagsAndReductions) {
    const int before = exec::max_threads();
    for (int threads : {1, 2}) {
        exec::set_threads(threads);
        const Index n = 5003;
        std::vector<Index> keep(n), at(n);
        for (Index i = 0; i < n; ++i) keep[i] = (i % 3 != 0);
        const Index kept = HostSpace::exclusive_scan(n, keep.data(), at.data());
        Index run = 0;
        for (Index i = 0; i < n; ++i) {
            EXPECT_EQ(at[i], run);
            run += keep[i];
        }
        EXPECT_EQ(kept, run);
        EXPECT_EQ(HostSpace::first_where(n, sph::Dropped{keep.data()}), 0);
        EXPECT_EQ(HostSpace::first_where(n, [](Index i) { return i == 4000 || i == 4500; }), 4000);
        EXPECT_EQ(HostSpace::first_where(n, [](Index) { return false; }), n);
        EXPECT_DOUBLE_EQ(HostSpace::max_of(n, [](Index i) { return Real(i % 1000); }), 999.0);
        EXPECT_DOUBLE_EQ(HostSpace::sum_of(n, [](Index) { return Real(0.5); }), 0.5 * n);
    }
    exec::set_threads(before);
}
