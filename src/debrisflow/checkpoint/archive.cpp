#include "debrisflow/checkpoint/archive.hpp"
#include <fmt/format.h>

namespace debrisflow::checkpoint {

void Archive::raw(void* p, std::size_t n) {
    if (saving_) {
        const char* c = static_cast<const char*>(p);
        bytes_.insert(bytes_.end(), c, c + n);
        return;
    }
    require(n <= bytes_.size() - pos_, "a value");
    std::memcpy(p, bytes_.data() + pos_, n);
    pos_ += n;
}

void Archive::io(std::string& s) {
    std::uint64_t n = s.size();
    io(n);
    if (!saving_) {
        require(n <= bytes_.size() - pos_, "a string");
        s.assign(bytes_.data() + pos_, std::size_t(n));
        pos_ += std::size_t(n);
        return;
    }
    bytes_.insert(bytes_.end(), s.begin(), s.end());
}

void Archive::section(const std::string& tag) {
    std::string s = tag;
    io(s);
    if (!saving_ && s != tag)
        fail(fmt::format("expected the section '{}' but found '{}' (written by a build that "
                         "stores other state)",
                         tag, s.substr(0, 40)));
}

void Archive::finish() const {
    if (!saving_ && pos_ != bytes_.size())
        fail(fmt::format("{} bytes left after the last section", bytes_.size() - pos_));
}

void Archive::fail(const std::string& what) const {
    throw CheckpointError(fmt::format("checkpoint {}: {}", file_, what));
}

void Archive::require(bool ok, const char* what) const {
    if (!ok) fail(fmt::format("ends inside {} at byte {} of {}", what, pos_, bytes_.size()));
}

} // namespace debrisflow::checkpoint
