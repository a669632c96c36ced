#include "debrisflow/io/config_table.hpp"
#include "debrisflow/core/error.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::io {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min(
                {prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string type_name(const toml::node& n) {
    switch (n.type()) {
    case toml::node_type::table:
        return "a table";
    case toml::node_type::array:
        return "an array";
    case toml::node_type::string:
        return "a string";
    case toml::node_type::integer:
        return "an integer";
    case toml::node_type::floating_point:
        return "a float";
    case toml::node_type::boolean:
        return "a boolean";
    default:
        return "a date/time";
    }
}

} // namespace

ConfigTable::ConfigTable(const toml::table& table, std::string file, std::string prefix)
    : ConfigTable(table, std::move(file), std::move(prefix), nullptr) {}

ConfigTable::ConfigTable(std::shared_ptr<const toml::table> document, std::string file)
    : ConfigTable(*document, std::move(file), "", document) {}

ConfigTable::ConfigTable(const toml::table& table, std::string file, std::string prefix,
                         std::shared_ptr<const toml::table> document)
    : table_(&table), file_(std::move(file)), prefix_(std::move(prefix)),
      document_(std::move(document)), used_(std::make_shared<std::set<std::string>>()) {}

std::string ConfigTable::where(const std::string& key) const {
    const toml::node* n = node(key);
    const auto& src = n ? n->source() : table_->source();
    std::string full = prefix_.empty() ? key : prefix_ + "." + key;
    if (src.begin.line == 0) return fmt::format("{} (--set override): key '{}'", file_, full);
    return fmt::format("{}:{}:{}: key '{}'", file_, src.begin.line, src.begin.column, full);
}

Origin ConfigTable::origin() const {
    Origin o;
    o.file_ = file_;
    o.prefix_ = prefix_;
    const auto& src = table_->source();
    o.block_ = {long(src.begin.line), long(src.begin.column)};
    for (const auto& [k, v] : *table_)
        o.keys_[std::string(k.str())] = {long(v.source().begin.line),
                                         long(v.source().begin.column)};
    return o;
}

void ConfigTable::fail(const std::string& key, const std::string& message) const {
    throw InputError(fmt::format("{}: {}", where(key), message));
}

const toml::node* ConfigTable::node(const std::string& key) const {
    used_->insert(key);
    return table_->get(key);
}

bool ConfigTable::has(const std::string& key) const {
    return table_->get(key) != nullptr;
}

const toml::node& ConfigTable::require(const std::string& key) const {
    const toml::node* n = node(key);
    if (!n) {
        const auto& src = table_->source();
        std::string full = prefix_.empty() ? key : prefix_ + "." + key;
        throw InputError(fmt::format("{}:{}:{}: missing required key '{}'", file_, src.begin.line,
                                     src.begin.column, full));
    }
    return *n;
}

Real ConfigTable::real(const std::string& key) const {
    const toml::node& n = require(key);
    if (auto v = n.value_exact<double>()) {
        if (!std::isfinite(*v)) fail(key, fmt::format("must be a finite number, got {}", *v));
        return Real(*v);
    }
    if (auto v = n.value_exact<std::int64_t>()) return Real(*v);
    fail(key, "expected a number, found " + type_name(n));
}

Real ConfigTable::real(const std::string& key, Real fallback) const {
    return has(key) ? real(key) : (used_->insert(key), fallback);
}

Real ConfigTable::positive(const std::string& key) const {
    Real v = real(key);
    if (!(v > 0)) fail(key, fmt::format("must be > 0, got {}", v));
    return v;
}

Real ConfigTable::positive(const std::string& key, Real fallback) const {
    return has(key) ? positive(key) : (used_->insert(key), fallback);
}

long ConfigTable::integer(const std::string& key, long fallback) const {
    const toml::node* n = node(key);
    if (!n) return fallback;
    if (auto v = n->value_exact<std::int64_t>()) return long(*v);
    fail(key, "expected an integer, found " + type_name(*n));
}

long ConfigTable::integer(const std::string& key, long fallback, long lo, long hi) const {
    const long v = integer(key, fallback);
    if (v < lo || v > hi) fail(key, fmt::format("must be within {}..{}, got {}", lo, hi, v));
    return v;
}

bool ConfigTable::boolean(const std::string& key, bool fallback) const {
    const toml::node* n = node(key);
    if (!n) return fallback;
    if (auto v = n->value_exact<bool>()) return *v;
    fail(key, "expected true or false, found " + type_name(*n));
}

std::string ConfigTable::string(const std::string& key) const {
    const toml::node& n = require(key);
    if (auto v = n.value_exact<std::string>()) return *v;
    fail(key, "expected a string, found " + type_name(n));
}

std::string ConfigTable::string(const std::string& key, const std::string& fallback) const {
    return has(key) ? string(key) : (used_->insert(key), fallback);
}

namespace {
bool name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
}
constexpr std::size_t max_name_length = 64;
} // namespace

std::string ConfigTable::name(const std::string& key) const {
    const std::string v = string(key);
    if (v.empty() || v.size() > max_name_length)
        fail(key,
             fmt::format("a name needs 1 to {} characters, got {}", max_name_length, v.size()));
    if (v.front() == '.') fail(key, "a name must not start with '.'");
    for (const char c : v)
        if (!name_char(c))
            fail(key, fmt::format("a name may hold letters, digits, '_', '-' and '.' only (it "
                                  "becomes a file name); found byte 0x{:02x}",
                                  unsigned(static_cast<unsigned char>(c))));
    return v;
}

std::string file_safe_name(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (out.size() == max_name_length) break;
        out += name_char(c) ? c : '_';
    }
    if (out.empty()) return "case";
    if (out.front() == '.') out.front() = '_';
    return out;
}

std::string ConfigTable::choice(const std::string& key, const std::vector<std::string>& names,
                                const std::string& fallback) const {
    const std::string v = fallback.empty() ? string(key) : string(key, fallback);
    if (std::find(names.begin(), names.end(), v) != names.end()) return v;
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "\"" : ", \"") + n + "\"";
    fail(key, fmt::format("unknown choice \"{}\"; expected one of {}", v, list));
}

namespace {
// A TOML integer or float as a Real.
std::optional<Real> number(const toml::node& e) {
    if (auto v = e.value_exact<double>()) return Real(*v);
    if (auto w = e.value_exact<std::int64_t>()) return Real(*w);
    return std::nullopt;
}
} // namespace

std::vector<Real> ConfigTable::reals(const std::string& key) const {
    const toml::node& n = require(key);
    const toml::array* arr = n.as_array();
    if (!arr) fail(key, "expected an array of numbers, found " + type_name(n));
    std::vector<Real> out;
    for (const auto& e : *arr) {
        const auto v = number(e);
        if (!v) fail(key, "expected an array of numbers, found an element that is " + type_name(e));
        if (!std::isfinite(*v))
            fail(key, fmt::format("every element must be a finite number, got {}", *v));
        out.push_back(*v);
    }
    return out;
}

std::vector<std::vector<Real>> ConfigTable::rows(const std::string& key, std::size_t width) const {
    const toml::node& n = require(key);
    const toml::array* arr = n.as_array();
    const std::string expect = fmt::format("expected an array of [{} numbers] rows", width);
    if (!arr) fail(key, expect + ", found " + type_name(n));
    std::vector<std::vector<Real>> out;
    for (const auto& row : *arr) {
        const toml::array* r = row.as_array();
        if (!r || r->size() != width) fail(key, expect);
        std::vector<Real> vals;
        for (const auto& e : *r) {
            const auto v = number(e);
            if (!v) fail(key, expect + "; found an element that is " + type_name(e));
            if (!std::isfinite(*v))
                fail(key, fmt::format("every element must be a finite number, got {}", *v));
            vals.push_back(*v);
        }
        out.push_back(vals);
    }
    return out;
}

std::vector<std::string> ConfigTable::strings(const std::string& key) const {
    const toml::node& n = require(key);
    const toml::array* arr = n.as_array();
    if (!arr) fail(key, "expected an array of strings, found " + type_name(n));
    std::vector<std::string> out;
    for (const auto& e : *arr) {
        if (auto v = e.value_exact<std::string>())
            out.push_back(*v);
        else
            fail(key, "expected an array of strings");
    }
    return out;
}

Vec3 ConfigTable::vec3(const std::string& key, int dim) const {
    const auto v = reals(key);
    if (v.size() == 3) return {v[0], v[1], v[2]};
    if (v.size() == 2 && dim == 2) return {v[0], 0, v[1]};
    fail(key, dim == 2 ? "expected [x, z] or [x, y, z]" : "expected [x, y, z]");
}

Vec3 ConfigTable::vec3(const std::string& key, int dim, Vec3 fallback) const {
    return has(key) ? vec3(key, dim) : (used_->insert(key), fallback);
}

std::optional<ConfigTable> ConfigTable::table(const std::string& key) const {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    const toml::table* t = n->as_table();
    if (!t) fail(key, "expected a table, found " + type_name(*n));
    return ConfigTable(*t, file_, prefix_.empty() ? key : prefix_ + "." + key, document_);
}

std::vector<ConfigTable> ConfigTable::tables(const std::string& key) const {
    std::vector<ConfigTable> out;
    const toml::node* n = node(key);
    if (!n) return out;
    const toml::array* arr = n->as_array();
    if (!arr) fail(key, "expected an array of tables ([[" + key + "]]), found " + type_name(*n));
    std::size_t i = 0;
    for (const auto& e : *arr) {
        const toml::table* t = e.as_table();
        if (!t) fail(key, "expected an array of tables ([[" + key + "]])");
        out.push_back(ConfigTable(
            *t, file_, (prefix_.empty() ? key : prefix_ + "." + key) + "." + std::to_string(i++),
            document_));
    }
    return out;
}

void ConfigTable::finish() const {
    for (const auto& [k, v] : *table_) {
        const std::string key(k.str());
        if (used_->count(key)) continue;
        std::string best;
        std::size_t best_d = 99;
        for (const auto& u : *used_) {
            const std::size_t d = edit_distance(key, u);
            if (d < best_d) best_d = d, best = u;
        }
        std::string hint = best_d <= 3 ? fmt::format(" (did you mean '{}'?)", best) : "";
        const auto& src = v.source();
        std::string full = prefix_.empty() ? key : prefix_ + "." + key;
        if (src.begin.line == 0)
            throw InputError(
                fmt::format("{} (--set override): unknown key '{}'{}", file_, full, hint));
        throw InputError(fmt::format("{}:{}:{}: unknown key '{}'{}", file_, src.begin.line,
                                     src.begin.column, full, hint));
    }
}

void apply_override(toml::table& doc, const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--set " + assignment + ": expected key=value");
    const std::string path = assignment.substr(0, eq);
    const std::string text = assignment.substr(eq + 1);
    toml::node* target = &doc;
    std::vector<std::string> parts;
    for (std::size_t a = 0, b; a <= path.size(); a = b + 1) {
        b = path.find('.', a);
        if (b == std::string::npos) b = path.size();
        parts.push_back(path.substr(a, b - a));
    }
    // Parse the value as TOML; fall back to a plain string.
    toml::table parsed;
    try {
        parsed = toml::parse("v = " + text);
    } catch (const toml::parse_error&) {
        parsed = toml::parse("v = \"\"");
        parsed.insert_or_assign("v", text);
    }
    toml::node* value = parsed.get("v");
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const bool last = i + 1 == parts.size();
        const std::string& p = parts[i];
        if (auto* t = target->as_table()) {
            if (last) {
                t->insert_or_assign(p, *value);
                return;
            }
            toml::node* next = t->get(p);
            if (!next) {
                t->insert_or_assign(p, toml::table{});
                next = t->get(p);
            }
            target = next;
        } else if (auto* arr = target->as_array()) {
            std::size_t idx = 0;
            try {
                idx = std::stoul(p);
            } catch (...) {
                throw InputError("--set " + assignment + ": '" + p + "' is not an array index");
            }
            if (idx >= arr->size())
                throw InputError("--set " + assignment + ": index " + p + " is out of range");
            if (last) {
                arr->replace(arr->begin() + long(idx), *value);
                return;
            }
            target = arr->get(idx);
        } else {
            throw InputError("--set " + assignment + ": '" + p + "' is not inside a table");
        }
    }
}

} // namespace debrisflow::io
