#include "runner/execution/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <unistd.h>

namespace mhb {

bool stderr_is_terminal() {
    return ::isatty(STDERR_FILENO) == 1;
}

std::string format_duration(double seconds) {
    const auto total = static_cast<long long>(std::llround(std::max(0.0, seconds)));
    char buf[32];
    if (total >= 3600)
        std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", total / 3600, (total / 60) % 60, total % 60);
    else
        std::snprintf(buf, sizeof buf, "%lld:%02lld", total / 60, total % 60);
    return buf;
}

ProgressBar::ProgressBar(std::ostream& out, std::int64_t total, std::int64_t already, ProgressOptions options)
    : out_(out), total_(total), already_(already), options_(options),
      start_(std::chrono::steady_clock::now()), done_(already) {}

void ProgressBar::update(std::int64_t done, std::int64_t evaluations) {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = std::max(done_, done);
    evaluations_ += static_cast<double>(evaluations);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    // A terminal is redrawn a few times a second (and at the last run); a log gets a line per interval.
    const double interval = options_.terminal ? 0.2 : options_.line_interval;
    const bool due = last_draw_ < 0
                         ? elapsed >= std::max(options_.delay_seconds, options_.terminal ? 0.0 : interval)
                         : elapsed - last_draw_ >= interval;
    if (elapsed < options_.delay_seconds || !(due || (options_.terminal && shown_ && done_ == total_)))
        return;
    draw(elapsed);
}

void ProgressBar::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!shown_)
        return;
    if (options_.terminal) {
        draw(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
        out_ << '\n' << std::flush;
    }
    shown_ = false;
}

void ProgressBar::draw(double elapsed) {
    // Rates and the ETA extrapolate this session's pace; resumed runs took no time here.
    const std::int64_t done_here = done_ - already_;
    const double runs_per_second = elapsed > 0 ? static_cast<double>(done_here) / elapsed : 0.0;
    const double evaluations_per_second = elapsed > 0 ? evaluations_ / elapsed : 0.0;
    std::string eta = "--:--";
    if (done_here > 0)
        eta = format_duration(elapsed / static_cast<double>(done_here) * static_cast<double>(total_ - done_));
    const double fraction = total_ > 0 ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0;
    char line[256];
    if (options_.terminal) {
        constexpr int width = 30;
        std::string bar(static_cast<std::size_t>(fraction * width), '#');
        bar.resize(width, '.');
        std::snprintf(line, sizeof line,
                      "\r[%s] %lld/%lld runs  %.3g runs/s  %.3g evals/s  elapsed %s  eta %s ", bar.c_str(),
                      static_cast<long long>(done_), static_cast<long long>(total_), runs_per_second,
                      evaluations_per_second, format_duration(elapsed).c_str(), eta.c_str());
    } else {
        std::snprintf(line, sizeof line,
                      "progress: %lld/%lld runs (%.0f%%), %.3g runs/s, %.3g evals/s, elapsed %s, eta %s\n",
                      static_cast<long long>(done_), static_cast<long long>(total_), 100.0 * fraction,
                      runs_per_second, evaluations_per_second, format_duration(elapsed).c_str(), eta.c_str());
    }
    out_ << line << std::flush;
    shown_ = true;
    last_draw_ = elapsed;
}

} // namespace mhb
