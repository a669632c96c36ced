#include "debrisflow/io/toml_echo.hpp"
#include "debrisflow/io/quoted.hpp"
#include <cmath>
#include <fmt/format.h>
#include <sstream>

namespace debrisflow::io {

namespace {

bool bare_key(const std::string& k) {
    if (k.empty()) return false;
    for (const char c : k)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-'))
            return false;
    return true;
}

std::string key(const std::string& k) {
    return bare_key(k) ? k : quoted(k);
}

// Shortest round-trip decimal, always recognisable as a float.
std::string real(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::string s = fmt::format("{}", v);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string value(const toml::node& n);

std::string inline_table(const toml::table& t) {
    std::string o = "{";
    bool first = true;
    for (const auto& [k, v] : t) {
        o += (first ? " " : ", ") + key(std::string(k.str())) + " = " + value(v);
        first = false;
    }
    return o + (first ? "}" : " }");
}

std::string value(const toml::node& n) {
    if (auto v = n.value_exact<double>()) return real(*v);
    if (auto v = n.value_exact<std::int64_t>()) return std::to_string(*v);
    if (auto v = n.value_exact<bool>()) return *v ? "true" : "false";
    if (auto v = n.value_exact<std::string>()) return quoted(*v);
    if (const auto* a = n.as_array()) {
        std::string o = "[";
        for (std::size_t i = 0; i < a->size(); ++i) o += (i ? ", " : "") + value(*a->get(i));
        return o + "]";
    }
    if (const auto* t = n.as_table()) return inline_table(*t);
    std::ostringstream s; // dates and times: as toml++ writes them
    n.visit([&](const auto& x) { s << x; });
    return s.str();
}

bool array_of_tables(const toml::node& n) {
    const auto* a = n.as_array();
    return a && !a->empty() && a->is_array_of_tables();
}

// A table written as `key = { ... }` where the case wrote it so (and any table --set made).
bool inline_value(const toml::node& n) {
    const auto* t = n.as_table();
    return t && t->is_inline();
}

void write_table(std::string& out, const toml::table& t, const std::string& path) {
    for (const auto& [k, v] : t)
        if ((!v.is_table() || inline_value(v)) && !array_of_tables(v))
            out += key(std::string(k.str())) + " = " + value(v) + "\n";
    for (const auto& [k, v] : t) {
        const std::string name = (path.empty() ? "" : path + ".") + key(std::string(k.str()));
        if (inline_value(v)) continue;
        if (const auto* sub = v.as_table()) {
            out += "\n[" + name + "]\n";
            write_table(out, *sub, name);
        } else if (array_of_tables(v)) {
            for (const auto& e : *v.as_array()) {
                out += "\n[[" + name + "]]\n";
                write_table(out, *e.as_table(), name);
            }
        }
    }
}

} // namespace

std::string echo_toml(const toml::table& doc) {
    std::string out;
    write_table(out, doc, "");
    return out;
}

} // namespace debrisflow::io
