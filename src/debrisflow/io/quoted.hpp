#pragma once
#include <string>

namespace debrisflow::io {

// `s` in double quotes with quote, backslash and every control character escaped (\n, \t,
// \u00XX): a valid JSON string (RFC 8259 section 7) and TOML basic string (TOML 1.0) alike.
std::string quoted(const std::string& s);

} // namespace debrisflow::io
