#include "debrisflow/core/log.hpp"
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace debrisflow {

void Log::line(const std::string& s) {
    if (file_) file_ << s << std::endl;
    if (!quiet_) std::cout << s << std::endl;
}

void Log::progress(const std::string& s) {
    if (file_) file_ << s << std::endl;
    if (quiet_) return;
    std::cout << s << std::endl;
}

} // namespace debrisflow
