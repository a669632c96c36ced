#pragma once
#include <string>

namespace debrisflow::io {

// Makes `dir` ready for a new run's results. A folder that already holds results (a summary,
// a log, frames or probe files) is refused with InputError, so that a new run is never mixed
// with an old one, unless `overwrite`: then those results are removed first. Anything else
// in the folder is left alone.
void prepare_output_dir(const std::string& dir, bool overwrite);

} // namespace debrisflow::io
