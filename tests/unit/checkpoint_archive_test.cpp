// Checkpoint archive and file (checkpoint/): a symmetric save/load pass, refusals of damaged
// and truncated files, newest-first listing and pruning to the two newest.
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/checkpoint/checkpoint_file.hpp"
#include "debrisflow/core/vec3_k.hpp"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace debrisflow;
using checkpoint::Archive;
using checkpoint::CheckpointError;

namespace {
struct Sample {
    double t = 0;
    std::vector<Vec3> x;
    std::vector<std::vector<double>> rows;
    std::string name;
    std::unordered_map<std::uint64_t, double> last;
    void state(Archive& ar) {
        ar.section("sample");
        ar(t, x, rows, name, last);
    }
};

std::string temp_dir(const char* name) {
    const auto d = std::filesystem::temp_directory_path() / "debrisflow_tests" / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d.string();
}
} // namespace

TEST(CheckpointArchive, SavesAndLoadsEveryKindOfMemberBitForBit) {
    Sample a;
    a.t = 0.1 + 0.2; // not representable exactly: must come back identical
    a.x = {{1, 2, 3}, {-0.0, 1e-300, 4}};
    a.rows = {{1.5}, {}, {2, 3, 4}};
    a.name = "probe \"x\"";
    a.last = {{7, 0.5}, {3, -1.25}, {11, 2}};
    auto out = Archive::saving();
    a.state(out);
    Sample b;
    auto in = Archive::loading(out.bytes(), "mem");
    b.state(in);
    in.finish();
    EXPECT_EQ(std::memcmp(&a.t, &b.t, sizeof a.t), 0);
    ASSERT_EQ(b.x.size(), 2u);
    EXPECT_EQ(std::memcmp(a.x.data(), b.x.data(), 2 * sizeof(Vec3)), 0);
    EXPECT_EQ(a.rows, b.rows);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.last, b.last);
    // The same map inserted in another order saves the same bytes (sorted by key).
    Sample c = a;
    c.last.clear();
    for (std::uint64_t k : {11u, 3u, 7u}) c.last[k] = a.last[k];
    auto again = Archive::saving();
    c.state(again);
    EXPECT_EQ(out.bytes(), again.bytes());
}

TEST(CheckpointArchive, TruncationAndWrongSectionsAreNamed) {
    Sample a;
    a.x.assign(100, Vec3{1, 2, 3});
    auto out = Archive::saving();
    a.state(out);
    std::vector<char> cut(out.bytes().begin(), out.bytes().end() - 10);
    Sample b;
    auto in = Archive::loading(cut, "cut.dfc");
    try {
        b.state(in);
        FAIL() << "a truncated archive was read";
    } catch (const CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("checkpoint cut.dfc: ends inside"), std::string::npos)
            << e.what();
    }
    auto wrong = Archive::loading(out.bytes(), "other.dfc");
    try {
        wrong.section("grains");
        FAIL() << "a wrong section was accepted";
    } catch (const CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("expected the section 'grains' but found 'sample'"),
                  std::string::npos)
            << e.what();
    }
    // A huge count in a damaged file is refused before anything is allocated.
    std::vector<char> bad(out.bytes());
    const std::size_t count_at = 8 + 6 + 8; // tag length + "sample" + t
    for (std::size_t k = 0; k < 8; ++k) bad[count_at + k] = char(0x7f);
    auto huge = Archive::loading(bad, "huge.dfc");
    EXPECT_THROW(b.state(huge), CheckpointError);
}

TEST(CheckpointFile, ChecksumVersionTruncationAndPruning) {
    const std::string dir = temp_dir("checkpoint_file");
    const std::vector<char> payload(1000, 'x');
    for (long step : {10, 200, 3000}) {
        checkpoint::write_file(dir + "/" + checkpoint::file_name(step), payload);
        EXPECT_FALSE(std::filesystem::exists(dir + "/" + checkpoint::file_name(step) + ".tmp"));
    }
    auto files = checkpoint::list(dir);
    ASSERT_EQ(files.size(), 3u);
    EXPECT_NE(files[0].find("step_000000003000.dfc"), std::string::npos); // newest first
    std::ofstream(dir + "/step_000000009999.dfc.tmp") << "partial";
    checkpoint::prune(dir, 2);
    files = checkpoint::list(dir);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_NE(files[1].find("step_000000000200.dfc"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir + "/step_000000009999.dfc.tmp"));
    EXPECT_EQ(checkpoint::read_file(files[0]), payload);

    auto refused = [&](const std::string& what) {
        try {
            checkpoint::read_file(files[0]);
        } catch (const CheckpointError& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << "accepted: " << what;
    };
    {
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(500);
        f.put('y'); // one flipped byte in the payload
    }
    refused("corrupted: CRC-32");
    std::filesystem::resize_file(files[0], 600);
    refused("truncated or extended");
    std::filesystem::resize_file(files[0], 10);
    refused("truncated (10 bytes, no header)");
    {
        checkpoint::write_file(files[0], payload);
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(8);
        const std::uint32_t v = 99;
        f.write(reinterpret_cast<const char*>(&v), sizeof v);
    }
    refused("format version 99");
    {
        std::ofstream f(files[0], std::ios::binary);
        f << std::string(100, 'z');
    }
    refused("not a debrisflow checkpoint");
}
