#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace debrisflow::io {

// A TOML table being read into a spec. Every read marks the key as used; finish() rejects
// keys that were never read (typos) with a suggestion. Errors name file:line:column and the
// full dotted key, and are thrown as InputError.
class ConfigTable {
public:
    ConfigTable(const toml::table& table, std::string file, std::string prefix);

    bool has(const std::string& key) const;
    Real real(const std::string& key) const;
    Real real(const std::string& key, Real fallback) const;
    Real positive(const std::string& key) const;
    Real positive(const std::string& key, Real fallback) const;
    long integer(const std::string& key, long fallback) const;
    bool boolean(const std::string& key, bool fallback) const;
    std::string string(const std::string& key) const;
    std::string string(const std::string& key, const std::string& fallback) const;
    // A choice among `names` (model names, shape types ...).
    std::string choice(const std::string& key, const std::vector<std::string>& names,
                       const std::string& fallback = "") const;
    // [x, y, z]; in 2D also [x, z] (y = 0).
    Vec3 vec3(const std::string& key, int dim) const;
    Vec3 vec3(const std::string& key, int dim, Vec3 fallback) const;
    std::vector<Real> reals(const std::string& key) const;
    std::vector<std::string> strings(const std::string& key) const;
    // An array of arrays of numbers (table rows), each row of `width` numbers.
    std::vector<std::vector<Real>> rows(const std::string& key, std::size_t width) const;

    std::optional<ConfigTable> table(const std::string& key) const;
    std::vector<ConfigTable> tables(const std::string& key) const; // array of tables

    [[noreturn]] void fail(const std::string& key, const std::string& message) const;
    // Errors on any key that no reader asked for.
    void finish() const;
    std::string where(const std::string& key) const;
    const std::string& file() const { return file_; }

private:
    const toml::node* node(const std::string& key) const;
    const toml::node& require(const std::string& key) const;
    const toml::table* table_;
    std::string file_, prefix_;
    std::shared_ptr<std::set<std::string>> used_;
};

// Applies `--set a.b.c=value` to a parsed document (value parsed as TOML; a bare word that is
// not valid TOML is taken as a string). Array elements are addressed by index: probe.0.every.
void apply_override(toml::table& doc, const std::string& assignment);

} // namespace debrisflow::io
