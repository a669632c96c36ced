#include "debrisflow/core/log.hpp"
#include <iostream>

namespace debrisflow {

void Log::line(const std::string& s) {
    if (file_) file_ << s << std::endl;
    if (!quiet_) std::cout << s << std::endl;
}

} // namespace debrisflow
