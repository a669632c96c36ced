#pragma once

namespace debrisflow::app {

// The git revision the binary was built from (`git describe --always --dirty`) and its build
// options (build type, precision, compiler, OpenMP, CUDA); written at build time.
const char* build_revision();
const char* build_options();

} // namespace debrisflow::app
