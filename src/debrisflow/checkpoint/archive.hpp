#pragma once
#include "debrisflow/core/error.hpp"
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace debrisflow::checkpoint {

// A checkpoint that cannot be used: truncated, corrupted, of another format version or
// another case. Exit code 2, like bad input.
class CheckpointError : public InputError {
public:
    using InputError::InputError;
};

// One symmetric pass over a run's state: saving appends every member to a byte buffer,
// loading reads them back in the same order. Each class lists its members once, in
// state(Archive&), and the same code saves and restores. Numbers are stored as their bytes
// (a checkpoint is read back on the machine type that wrote it), so a restart continues bit
// for bit. Sections carry a tag that loading verifies, so a mismatch is named, not misread.
class Archive {
public:
    static Archive saving() { return Archive(true, {}); }
    static Archive loading(std::vector<char> bytes, std::string file) {
        Archive a(false, std::move(bytes));
        a.file_ = std::move(file);
        return a;
    }
    bool is_loading() const { return !saving_; }
    const std::vector<char>& bytes() const { return bytes_; }

    template <class T>
    requires std::is_trivially_copyable_v<T>
    void io(T& v) { raw(&v, sizeof(T)); }
    template <class T>
    requires std::is_trivially_copyable_v<T>
    void io(std::vector<T>& v) {
        std::uint64_t n = v.size();
        io(n);
        if (!saving_) {
            require(n <= (bytes_.size() - pos_) / (sizeof(T) ? sizeof(T) : 1), "an array");
            v.resize(std::size_t(n));
        }
        if (n) raw(v.data(), std::size_t(n) * sizeof(T));
    }
    void io(std::string& s);
    template <class T>
    requires(!std::is_trivially_copyable_v<T>) void io(std::vector<T>& v) {
        std::uint64_t n = v.size();
        io(n);
        if (!saving_) {
            require(n <= bytes_.size() - pos_, "a list");
            v.resize(std::size_t(n));
        }
        for (auto& e : v) io(e);
    }
    template <class K, class V> void io(std::unordered_map<K, V>& m) {
        // by key: a map's iteration order depends on its history, the file must not
        std::vector<K> keys;
        for (const auto& kv : m) keys.push_back(kv.first);
        std::sort(keys.begin(), keys.end());
        std::vector<V> values;
        for (const K& k : keys) values.push_back(m.at(k));
        io(keys);
        io(values);
        if (saving_) return;
        require(keys.size() == values.size(), "a map");
        m.clear();
        for (std::size_t i = 0; i < keys.size(); ++i) m.emplace(keys[i], values[i]);
    }
    template <class... T> void operator()(T&... v) { (io(v), ...); }

    // A list of structs that have padding, member by member (the padding's bytes are garbage,
    // and equal states must give equal files): columns(v, &S::a, &S::b, ...) must name every
    // member that matters.
    template <class S, class... M> void columns(std::vector<S>& v, M S::*... members) {
        std::uint64_t n = v.size();
        io(n);
        if (!saving_) {
            require(n <= bytes_.size() - pos_, "a table");
            v.assign(std::size_t(n), S{});
        }
        (column(v, members), ...);
    }

    // Writes the tag, or checks that the next bytes are this tag.
    void section(const std::string& tag);
    // Loading: every byte was read (the file holds nothing this build does not know).
    void finish() const;
    // Throws CheckpointError naming the file with `what`.
    [[noreturn]] void fail(const std::string& what) const;

private:
    template <class S, class M> void column(std::vector<S>& v, M S::*member) {
        std::vector<M> c;
        if (saving_)
            for (const S& s : v) c.push_back(s.*member);
        io(c);
        if (saving_) return;
        require(c.size() == v.size(), "a table's column");
        for (std::size_t i = 0; i < v.size(); ++i) v[i].*member = c[i];
    }
    Archive(bool saving, std::vector<char> bytes) : saving_(saving), bytes_(std::move(bytes)) {}
    void raw(void* p, std::size_t n);
    void require(bool ok, const char* what) const;
    bool saving_;
    std::vector<char> bytes_;
    std::size_t pos_ = 0;
    std::string file_;
};

// A list of (time, file) pairs: a VTK series' frames.
template <class Real>
void io_frames(Archive& ar, std::vector<std::pair<Real, std::string>>& frames) {
    std::vector<Real> t;
    std::vector<std::string> f;
    for (const auto& [time, file] : frames) t.push_back(time), f.push_back(file);
    ar(t, f);
    if (!ar.is_loading()) return;
    if (t.size() != f.size()) ar.fail("a frame list of mismatched lengths");
    frames.clear();
    for (std::size_t i = 0; i < t.size(); ++i) frames.emplace_back(t[i], f[i]);
}

} // namespace debrisflow::checkpoint
