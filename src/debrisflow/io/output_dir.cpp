#include "debrisflow/io/output_dir.hpp"
#include "debrisflow/core/error.hpp"
#include <filesystem>
#include <fmt/format.h>
#include <system_error>

namespace debrisflow::io {

namespace fs = std::filesystem;

namespace {
// Everything a run writes into its output folder.
const char* const results[] = {
    "summary.json",       "log.txt",         "case.toml", "vtk", "probes",
    "grains_settled.csv", "grains_final.csv"};
} // namespace

void prepare_output_dir(const std::string& dir, bool overwrite) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(fmt::format("--out {}: exists and is not a folder", dir));
    std::string found;
    for (const char* r : results)
        if (fs::exists(fs::path(dir) / r, ec))
            found += (found.empty() ? "" : ", ") + std::string(r);
    if (!found.empty() && !overwrite)
        throw InputError(fmt::format("--out {}: the folder holds the results of an earlier run "
                                     "({}); choose another --out, or pass --overwrite to replace "
                                     "them",
                                     dir, found));
    for (const char* r : results) {
        fs::remove_all(fs::path(dir) / r, ec);
        if (ec)
            throw InputError(
                fmt::format("--out {}: cannot remove the old {}: {}", dir, r, ec.message()));
    }
    fs::create_directories(dir, ec);
    if (ec)
        throw InputError(fmt::format("--out {}: cannot create the folder: {}", dir, ec.message()));
}

} // namespace debrisflow::io
