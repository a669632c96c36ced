#pragma once
// Reading digitised reference curves (CSV or whitespace, '#' comments) and comparing curves.
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace debrisflow::test {

using Curve = std::vector<std::pair<double, double>>;

// First two numeric columns of every data line; header and '#' lines are skipped.
inline Curve read_curve(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("missing reference file " + path);
    Curve c;
    std::string line;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::replace(line.begin(), line.end(), '\t', ' ');
        std::istringstream ss(line);
        double a, b;
        if (ss >> a >> b) c.emplace_back(a, b);
    }
    return c;
}

// Linear interpolation of y(x) on a curve sorted by x.
inline double interpolate(const Curve& c, double x) {
    if (x <= c.front().first) return c.front().second;
    for (std::size_t i = 1; i < c.size(); ++i)
        if (x <= c[i].first) {
            const auto [x0, y0] = c[i - 1];
            const auto [x1, y1] = c[i];
            return x1 > x0 ? y0 + (y1 - y0) * (x - x0) / (x1 - x0) : y1;
        }
    return c.back().second;
}

// "quantity,value" files (analytic/*_example.csv): value by quantity; non-numeric rows skipped.
inline std::map<std::string, double> read_key_values(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("missing reference file " + path);
    std::map<std::string, double> out;
    std::string line;
    while (std::getline(f, line)) {
        const auto comma = line.rfind(',');
        if (comma == std::string::npos) continue;
        try {
            std::size_t used = 0;
            const double v = std::stod(line.substr(comma + 1), &used);
            out[line.substr(0, comma)] = v;
        } catch (const std::exception&) {
        }
    }
    return out;
}

// A CSV table with a header line: one map from column name to cell text per data row.
inline std::vector<std::map<std::string, std::string>> read_table(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("missing reference file " + path);
    auto split = [](const std::string& line) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream ss(line);
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        return cells;
    };
    std::vector<std::map<std::string, std::string>> rows;
    std::string line;
    std::vector<std::string> header;
    while (std::getline(f, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        if (header.empty()) {
            header = split(line);
            continue;
        }
        const auto cells = split(line);
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < cells.size() && k < header.size(); ++k)
            row[header[k]] = cells[k];
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace debrisflow::test
