#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include "debrisflow/io/origin.hpp"
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace debrisflow::io {

// Upper bound of a boundary's particle layers: the kernel support (2h <= 8 dp) needs at most 8;
// more add nothing but memory.
inline constexpr long max_boundary_layers = 32;

// A TOML table being read into a spec. Every read marks the key as used; finish() rejects
// keys that were never read (typos) with a suggestion. Errors name file:line:column and the
// full dotted key, and are thrown as InputError. Every number read (alone, in an array or in
// table rows) must be finite: NaN and infinity are rejected where they are read.
class ConfigTable {
public:
    ConfigTable(const toml::table& table, std::string file, std::string prefix);
    // The root table of a whole document, which this table and the tables read from it keep
    // alive (so that a block can be read after the reader that found it has returned).
    ConfigTable(std::shared_ptr<const toml::table> document, std::string file);

    bool has(const std::string& key) const;
    Real real(const std::string& key) const;
    Real real(const std::string& key, Real fallback) const;
    Real positive(const std::string& key) const;
    Real positive(const std::string& key, Real fallback) const;
    long integer(const std::string& key, long fallback) const;
    // An integer within [lo, hi] (bounds that keep sizes and loops finite).
    long integer(const std::string& key, long fallback, long lo, long hi) const;
    bool boolean(const std::string& key, bool fallback) const;
    std::string string(const std::string& key) const;
    std::string string(const std::string& key, const std::string& fallback) const;
    // A name (of the case, a block, a probe): 1 to 64 letters, digits, '_', '-' or '.', not
    // starting with '.'; names become file names (probes/<name>.csv, out/<case name>).
    std::string name(const std::string& key) const;
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
    // The positions of this table and of every key it holds, for checks made after reading.
    Origin origin() const;
    const std::string& file() const { return file_; }

private:
    const toml::node* node(const std::string& key) const;
    const toml::node& require(const std::string& key) const;
    ConfigTable(const toml::table& table, std::string file, std::string prefix,
                std::shared_ptr<const toml::table> document);
    const toml::table* table_;
    std::string file_, prefix_;
    std::shared_ptr<const toml::table> document_; // null: the caller keeps the table alive
    std::shared_ptr<std::set<std::string>> used_;
};

// Applies `--set a.b.c=value` to a parsed document (value parsed as TOML; a bare word that is
// not valid TOML is taken as a string). Array elements are addressed by index: probe.0.every.
void apply_override(toml::table& doc, const std::string& assignment);

// `text` made into a name as name() accepts it: other characters become '_', cut to 64.
std::string file_safe_name(const std::string& text);

} // namespace debrisflow::io
