#pragma once
#include <string>
#include <toml++/toml.h>

namespace debrisflow::io {

// The case as TOML with every float in its shortest round-trip form (0.1, not
// 0.10000000000000001), so that the echoed case.toml reads as the user wrote it and parses back
// to the same values. Keys in table order; sub-tables as [a.b], arrays of tables as [[a]].
std::string echo_toml(const toml::table& doc);

} // namespace debrisflow::io
