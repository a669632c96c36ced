#pragma once
#include <fstream>
#include <string>

namespace debrisflow {

// Writes each line to the run's log file and, unless quiet, to the terminal.
class Log {
public:
    Log() = default;
    // append: continue an existing log (a restarted run).
    void open(const std::string& path, bool append = false) {
        file_.open(path, append ? std::ios::app : std::ios::out);
    }
    void set_quiet(bool q) { quiet_ = q; }
    void line(const std::string& s);

private:
    std::ofstream file_;
    bool quiet_ = false;
};

} // namespace debrisflow
