#include "debrisflow/checkpoint/checkpoint_file.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>
#include <zlib.h>

namespace debrisflow::checkpoint {

namespace {

constexpr char magic[8] = {'D', 'F', 'C', 'K', 'P', 'T', '\r', '\n'};

struct Header {
    char magic[8];
    std::uint32_t version;
    std::uint32_t crc;
    std::uint64_t size;
};
static_assert(sizeof(Header) == 24);

std::uint32_t crc_of(const std::vector<char>& bytes) {
    return std::uint32_t(crc32_z(crc32_z(0, nullptr, 0),
                                 reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

// write(2) all of [p, p + n), or throw.
void write_all(int fd, const char* p, std::size_t n, const std::string& path) {
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(
                fmt::format("cannot write checkpoint {}: {}", path, std::strerror(errno)));
        }
        p += w, n -= std::size_t(w);
    }
}

long step_of(const std::filesystem::path& p) {
    const std::string s = p.filename().string();
    if (s.size() < 10 || s.rfind("step_", 0) != 0 || p.extension() != ".dfc") return -1;
    const std::string digits = s.substr(5, s.size() - 9);
    if (digits.empty() || !std::all_of(digits.begin(), digits.end(), ::isdigit)) return -1;
    return std::stol(digits);
}

} // namespace

void write_file(const std::string& path, const std::vector<char>& payload) {
    Header h{};
    std::memcpy(h.magic, magic, sizeof magic);
    h.version = format_version;
    h.crc = crc_of(payload);
    h.size = payload.size();
    const std::string tmp = path + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0)
        throw std::runtime_error(
            fmt::format("cannot write checkpoint {}: {}", tmp, std::strerror(errno)));
    try {
        write_all(fd, reinterpret_cast<const char*>(&h), sizeof h, tmp);
        std::size_t first = payload.size();
        static int written = 0;
        if (const char* k = std::getenv("DEBRISFLOW_CHECKPOINT_KILL_AFTER_BYTES"); k && written++)
            first = std::min<std::size_t>(first, std::strtoull(k, nullptr, 10));
        write_all(fd, payload.data(), first, tmp);
        if (first < payload.size()) {
            ::fsync(fd);
            std::raise(SIGKILL); // fault injection: killed while writing
        }
        if (::fsync(fd) != 0)
            throw std::runtime_error(
                fmt::format("cannot flush checkpoint {}: {}", tmp, std::strerror(errno)));
    } catch (...) {
        ::close(fd);
        std::remove(tmp.c_str());
        throw;
    }
    ::close(fd);
    std::filesystem::rename(tmp, path);
    // The rename itself reaches the disk with the directory.
    const std::string dir = std::filesystem::path(path).parent_path().string();
    const int dfd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

std::vector<char> read_file(const std::string& path) {
    auto fail = [&](const std::string& what) -> std::vector<char> {
        throw CheckpointError(fmt::format("checkpoint {}: {}", path, what));
    };
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail("cannot be opened");
    in.seekg(0, std::ios::end);
    const auto length = std::uint64_t(in.tellg());
    in.seekg(0);
    Header h{};
    if (length < sizeof h) return fail(fmt::format("truncated ({} bytes, no header)", length));
    in.read(reinterpret_cast<char*>(&h), sizeof h);
    if (std::memcmp(h.magic, magic, sizeof magic) != 0)
        return fail("not a debrisflow checkpoint (wrong magic bytes)");
    if (h.version != format_version)
        return fail(fmt::format("format version {}, this build reads version {}", h.version,
                                format_version));
    if (length - sizeof h != h.size)
        return fail(fmt::format("truncated or extended: the header announces {} bytes of state, "
                                "the file holds {}",
                                h.size, length - sizeof h));
    std::vector<char> payload(std::size_t(h.size));
    in.read(payload.data(), std::streamsize(payload.size()));
    if (!in) return fail("cannot be read");
    if (crc_of(payload) != h.crc)
        return fail(fmt::format("corrupted: CRC-32 {:08x} does not match the stored {:08x}",
                                crc_of(payload), h.crc));
    return payload;
}

std::string file_name(long step) {
    return fmt::format("step_{:012d}.dfc", step);
}

std::vector<std::string> list(const std::string& dir) {
    std::vector<std::pair<long, std::string>> found;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (const long s = step_of(e.path()); s >= 0) found.emplace_back(s, e.path().string());
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a > b; });
    std::vector<std::string> out;
    for (auto& f : found) out.push_back(std::move(f.second));
    return out;
}

void prune(const std::string& dir, int keep) {
    const auto files = list(dir);
    for (std::size_t i = std::size_t(keep); i < files.size(); ++i)
        std::filesystem::remove(files[i]);
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().extension() == ".tmp") std::filesystem::remove(e.path(), ec);
}

} // namespace debrisflow::checkpoint
