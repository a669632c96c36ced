#pragma once
#include <fstream>
#include <string>

namespace debrisflow {

// Writes each line to the run's log file and, unless quiet, to the terminal.
class Log {
public:
    Log() = default;
    void open(const std::string& path) { file_.open(path); }
    void set_quiet(bool q) { quiet_ = q; }
    void line(const std::string& s);

private:
    std::ofstream file_;
    bool quiet_ = false;
};

} // namespace debrisflow
