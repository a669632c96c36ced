#include "debrisflow/io/origin.hpp"
#include <fmt/format.h>

namespace debrisflow::io {

std::string Origin::format(const Position& p, const std::string& what) const {
    if (file_.empty()) return what;
    if (p.line == 0) return fmt::format("{} (--set override): {}", file_, what);
    return fmt::format("{}:{}:{}: {}", file_, p.line, p.column, what);
}

std::string Origin::at(const std::string& key) const {
    const std::string full = prefix_.empty() ? key : prefix_ + "." + key;
    const auto it = keys_.find(key);
    return format(it == keys_.end() ? block_ : it->second, "key '" + full + "'");
}

std::string Origin::block() const {
    return format(block_, prefix_.empty() ? std::string("top level") : "[" + prefix_ + "]");
}

} // namespace debrisflow::io
