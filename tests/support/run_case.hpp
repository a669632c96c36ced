#pragma once
// Helpers for tests: write a case from TOML text and build it; find reference data.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <filesystem>
#include <fstream>
#include <string>

namespace debrisflow::test {

inline std::string write_temp_case(const std::string& name, const std::string& toml) {
    const auto dir = std::filesystem::temp_directory_path() / "debrisflow_tests";
    std::filesystem::create_directories(dir);
    const auto path = dir / (name + ".toml");
    std::ofstream(path) << toml;
    return path.string();
}

inline io::CaseSpec case_from_toml(const std::string& name, const std::string& toml,
                                   const std::vector<std::string>& sets = {}) {
    return io::read_case(write_temp_case(name, toml), sets);
}

// The message of the InputError that reading and building the case raises ("" when it builds).
inline std::string input_error_of(const std::string& name, const std::string& toml) {
    try {
        app::Simulation sim(case_from_toml(name, toml));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// ../shared/reference/<rel> beside the project root.
inline std::string reference(const std::string& rel) {
    return std::string(DEBRISFLOW_SOURCE_DIR) + "/../shared/reference/" + rel;
}

} // namespace debrisflow::test
