#pragma once
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
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

    // Position of Model in the list (the index a device-side table stores).
    template <class Model> static constexpr std::size_t index_of() {
        std::size_t i = 0, k = 0;
        (void)(((std::is_same_v<Model, Models> ? (i = k, true) : (++k, false))) || ...);
        return i;
    }

    // Calls f.template operator()<Model>() for the model at position `index`.
    template <class F> static auto visit_index(std::size_t index, F&& f) {
        using R = decltype(f.template operator()<std::variant_alternative_t<0, Variant>>());
        std::size_t k = 0;
        if constexpr (std::is_void_v<R>) {
            (void)((index == k++ ? (f.template operator()<Models>(), true) : false) || ...);
        } else {
            std::optional<R> out;
            (void)((index == k++ ? (out.emplace(f.template operator()<Models>()), true) : false) ||
                   ...);
            if (!out) throw std::out_of_range("model index out of range");
            return std::move(*out);
        }
    }

    // Calls f.template operator()<Model>() for every model, in order.
    template <class F> static void for_each(F&& f) { (f.template operator()<Models>(), ...); }

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
