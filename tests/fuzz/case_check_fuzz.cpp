// libFuzzer target: the path of `debrisflow check` on a case file's text (read, validate,
// estimate, build, step estimate). Any outcome but success or InputError is a defect: a crash,
// a sanitizer report, another exception, a hang (libFuzzer's -timeout) or an allocation beyond
// -rss_limit_mb. Built with -DDEBRISFLOW_FUZZ=ON and clang (tests/fuzz/README.md).
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/app/step_estimate.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/core/memory_budget.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace debrisflow;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // A small budget keeps every accepted case quick to build; refusals are InputErrors.
    set_memory_budget_bytes(64.0 * 1024 * 1024);
    exec::set_threads(1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return -1; // case files are a few kilobytes
    const std::string text(reinterpret_cast<const char*>(data), size);
    // Relative mesh and state files resolve against cases/, as for a case stored there.
    const std::string path = DEBRISFLOW_SOURCE_DIR "/cases/fuzz_input.toml";
    try {
        const io::CaseSpec spec = io::read_case_text(text, path, {});
        app::Simulation sim(spec);
        app::require_feasible_steps(sim);
    } catch (const InputError&) {
        // the expected answer to bad input
    } catch (const std::exception& e) {
        std::fprintf(stderr, "not an InputError: %s\n", e.what());
        std::abort();
    }
    return 0;
}
