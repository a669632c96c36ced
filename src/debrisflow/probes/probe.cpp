#include "debrisflow/probes/probe.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/core/error.hpp"
#include <filesystem>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::probes {

void Probe::open(const std::string& dir) {
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/" + name_ + ".csv";
    if (resume_bytes_ >= 0) {
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (ec || size < std::uintmax_t(resume_bytes_))
            throw checkpoint::CheckpointError(fmt::format(
                "{} holds {} bytes, fewer than the {} the checkpoint wrote: the output folder "
                "does not belong to this checkpoint",
                path, ec ? 0 : size, resume_bytes_));
        std::filesystem::resize_file(path, std::uintmax_t(resume_bytes_));
        // in | out keeps the content; at its end, tellp() gives the length a later checkpoint
        // records even before this run writes a row
        csv_.open(path, std::ios::in | std::ios::out);
        csv_.seekp(0, std::ios::end);
        if (!csv_) throw InputError("cannot write probe file " + path);
    } else {
        csv_.open(path);
        if (!csv_) throw InputError("cannot write probe file " + path);
        csv_ << "time [s]";
        for (const auto& c : columns()) csv_ << "," << c;
        csv_ << "\n";
    }
    open_extra(dir);
}

void Probe::record(Real t, const ProbeContext& ctx) {
    const auto v = sample(t, ctx);
    after_sample(t, v);
    if (peak_.empty()) {
        peak_ = v;
        peak_t_.assign(v.size(), t);
    }
    for (std::size_t k = 0; k < v.size(); ++k)
        if (v[k] > peak_[k]) {
            peak_[k] = v[k];
            peak_t_[k] = t;
        }
    last_ = v;
    ++samples_;
    history_.push_back({t});
    history_.back().insert(history_.back().end(), v.begin(), v.end());
    if (csv_) {
        csv_ << fmt::format("{:.9g}", t);
        for (Real x : v) csv_ << fmt::format(",{:.9g}", x);
        csv_ << "\n";
    }
}

void Probe::state(checkpoint::Archive& ar) {
    ar.section("probe " + name_);
    std::int64_t bytes = -1;
    if (!ar.is_loading() && csv_.is_open()) {
        csv_.flush();
        bytes = std::int64_t(csv_.tellp());
    }
    ar(history_, peak_, peak_t_, last_, samples_, bytes);
    if (ar.is_loading()) resume_bytes_ = bytes;
    extra_state(ar);
}

Real Probe::mean(std::size_t column, Real t0, Real t1) const {
    Real sum = 0;
    long n = 0;
    for (const auto& row : history_)
        if (row[0] >= t0 && row[0] <= t1) {
            sum += row[column + 1];
            ++n;
        }
    return n ? sum / Real(n) : std::numeric_limits<Real>::quiet_NaN();
}

Real peak_moving_mean(const std::vector<Real>& t, const std::vector<Real>& v, Real window) {
    Real best = std::numeric_limits<Real>::quiet_NaN();
    if (t.size() < 2) return best;
    // integral from the first sample by the trapezoid rule, at every sample
    std::vector<Real> integral(t.size(), 0);
    for (std::size_t k = 1; k < t.size(); ++k)
        integral[k] = integral[k - 1] + Real(0.5) * (t[k] - t[k - 1]) * (v[k] + v[k - 1]);
    // the integral at x, the samples joined linearly; hint: a sample at or after x
    auto integral_at = [&](Real x, std::size_t hint) {
        while (hint > 0 && t[hint] > x) --hint;
        const std::size_t a = hint, b = std::min(hint + 1, t.size() - 1);
        if (b == a || t[b] == t[a]) return integral[a];
        const Real vx = v[a] + (x - t[a]) / (t[b] - t[a]) * (v[b] - v[a]);
        return integral[a] + Real(0.5) * (x - t[a]) * (v[a] + vx);
    };
    for (std::size_t k = 1; k < t.size(); ++k) {
        if (t[k] - window < t[0] - Real(1e-12)) continue;
        const Real m = (integral[k] - integral_at(t[k] - window, k)) / window;
        if (!(m <= best)) best = m;
    }
    return best;
}

Real Probe::peak_window_mean(std::size_t column, Real window) const {
    if (every_ > Real(0.5) * window) return std::numeric_limits<Real>::quiet_NaN();
    std::vector<Real> t, v;
    for (const auto& row : history_) {
        t.push_back(row[0]);
        v.push_back(row[column + 1]);
    }
    return peak_moving_mean(t, v, window);
}

} // namespace debrisflow::probes
