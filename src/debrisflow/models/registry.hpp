#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace debrisflow::models {

// A model family: one type list yields the std::variant and the name table.
// Each model type has `static constexpr const char* name`.
template <class... Models> struct Registry {
    using Variant = std::variant<Models...>;

    static std::vector<std::string> names() { return {Models::name...}; }

    static bool has(const std::string& name) { return ((name == Models::name) || ...); }

    static std::string choices() {
        std::string s;
        ((s += (s.empty() ? "" : ", ") + std::string("\"") + Models::name + "\""), ...);
        return s;
    }

    // Calls f.template operator()<Model>() for the model called `name`.
    template <class F> static auto visit_name(const std::string& name, F&& f) {
        using R = decltype(f.template operator()<std::variant_alternative_t<0, Variant>>());
        if constexpr (std::is_void_v<R>) {
            bool found =
                ((name == Models::name ? (f.template operator()<Models>(), true) : false) || ...);
            if (!found) throw std::invalid_argument("unknown model \"" + name + "\"");
        } else {
            std::optional<R> out;
            (void)((name == Models::name ? (out.emplace(f.template operator()<Models>()), true)
                                         : false) ||
                   ...);
            if (!out) throw std::invalid_argument("unknown model \"" + name + "\"");
            return std::move(*out);
        }
    }
};

} // namespace debrisflow::models
