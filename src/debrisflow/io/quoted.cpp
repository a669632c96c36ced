#include "debrisflow/io/quoted.hpp"
#include <fmt/format.h>

namespace debrisflow::io {

std::string quoted(const std::string& s) {
    std::string o = "\"";
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\')
            o += {'\\', c};
        else if (c == '\n')
            o += "\\n";
        else if (c == '\t')
            o += "\\t";
        else if (u < 0x20 || u == 0x7f)
            o += fmt::format("\\u{:04x}", unsigned(u));
        else
            o += c;
    }
    return o + "\"";
}

} // namespace debrisflow::io
