#pragma once
#include "debrisflow/io/config_table.hpp"
#include <string>
#include <vector>

namespace debrisflow::io {

// Lookups by name in the case's lists (materials, walls, solids ...): elements with `name`.

// The element called `name`, or null.
template <class T> const T* find_named(const std::vector<T>& items, const std::string& name) {
    for (const auto& x : items)
        if (x.name == name) return &x;
    return nullptr;
}

// Its index, or -1.
template <class T> int index_named(const std::vector<T>& items, const std::string& name) {
    const T* x = find_named(items, name);
    return x ? int(x - items.data()) : -1;
}

// Fails `key` of the table unless an element is called `name`: "no <block> named "<name>"".
template <class T>
void require_named(const ConfigTable& t, const std::string& key, const std::vector<T>& items,
                   const std::string& name, const std::string& block) {
    if (!find_named(items, name)) t.fail(key, "no " + block + " named \"" + name + "\"");
}

} // namespace debrisflow::io
