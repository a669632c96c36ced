#pragma once
// Command line and case loading shared by the GPU checks:
//   CHECK CASE.toml [--set key=value]... [--advance T] [--repeat R] [--tolerance E]
// --advance runs the case on the host to time T first, so that the state is a flowing one.
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace debrisflow::gpu {

struct CheckOptions {
    std::string path;
    std::vector<std::string> overrides;
    Real advance = 0;
    int repeat = 5;
    double tolerance = 1e-9;

    static CheckOptions parse(int argc, char** argv) {
        CheckOptions o;
        for (int k = 1; k < argc; ++k) {
            const std::string a = argv[k];
            auto value = [&]() -> std::string {
                if (k + 1 >= argc) throw std::runtime_error(a + " needs a value");
                return argv[++k];
            };
            if (a == "--set")
                o.overrides.push_back(value());
            else if (a == "--advance")
                o.advance = std::stod(value());
            else if (a == "--repeat")
                o.repeat = std::stoi(value());
            else if (a == "--tolerance")
                o.tolerance = std::stod(value());
            else if (o.path.empty())
                o.path = a;
            else
                throw std::runtime_error("unexpected argument " + a);
        }
        if (o.path.empty())
            throw std::runtime_error("usage: CASE.toml [--set key=value]... [--advance T] "
                                     "[--repeat R] [--tolerance E]");
        return o;
    }

    // The case assembled and run on the host to t = advance.
    std::unique_ptr<app::Simulation> load() const {
        auto sim = std::make_unique<app::Simulation>(io::read_case(path, overrides));
        if (advance > 0) {
            app::RunOptions run;
            run.quiet = true;
            run.until = advance;
            sim->run(run);
        }
        return sim;
    }
};

// Exit status of a check that found no GPU (ctest's SKIP_RETURN_CODE).
constexpr int no_gpu_status = 77;

} // namespace debrisflow::gpu
