#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/core/error.hpp"
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

namespace debrisflow {

namespace {
double physical_memory() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? double(pages) * double(page) : 16.0 * (1L << 30);
}
double& budget() {
    static double b = physical_memory();
    return b;
}
} // namespace

double memory_budget_bytes() {
    return budget();
}

void set_memory_budget_bytes(double bytes) {
    budget() = bytes;
}

double resident_bytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    long size = 0, resident = 0;
    const bool ok = std::fscanf(f, "%ld %ld", &size, &resident) == 2;
    std::fclose(f);
    const long page = sysconf(_SC_PAGE_SIZE);
    return ok && page > 0 ? double(resident) * double(page) : 0;
}

void require_memory(double bytes, const std::string& what) {
    const double held = resident_bytes(), budget = memory_budget_bytes();
    if (!(held + bytes <= budget))
        throw OutOfMemoryError(fmt::format(
            "{} needs {} more, with {} already in use, beyond the memory budget of {} (the "
            "machine's memory, or --max-memory); coarsen the case (dp) or run it on a larger "
            "machine",
            what, format_bytes(bytes), format_bytes(held), format_bytes(budget)));
}

std::string format_bytes(double bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    int u = 0;
    while (u < 4 && bytes >= 1024) bytes /= 1024, ++u;
    return bytes < 1e4 ? fmt::format("{:.3g} {}", bytes, units[u])
                       : fmt::format("{:.2g} {}", bytes, units[u]);
}

double parse_bytes(const std::string& text) {
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        throw InputError("--max-memory " + text + ": expected a size such as 4G or 512M");
    }
    std::string unit = text.substr(used);
    if (unit.size() == 3 && (unit[1] == 'i' || unit[1] == 'I') &&
        (unit[2] == 'B' || unit[2] == 'b'))
        unit = unit.substr(0, 1);
    double scale = 1;
    if (unit == "K" || unit == "k")
        scale = 1024.0;
    else if (unit == "M" || unit == "m")
        scale = 1024.0 * 1024;
    else if (unit == "G" || unit == "g")
        scale = 1024.0 * 1024 * 1024;
    else if (unit == "T" || unit == "t")
        scale = 1024.0 * 1024 * 1024 * 1024;
    else if (!unit.empty() && unit != "B" && unit != "b")
        throw InputError("--max-memory " + text + ": unknown unit '" + unit +
                         "' (use K, M, G or T)");
    v *= scale;
    if (!std::isfinite(v) || !(v >= 1024 * 1024))
        throw InputError("--max-memory " + text + ": must be a finite size of at least 1M");
    return v;
}

} // namespace debrisflow
