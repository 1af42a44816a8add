#include "runner/progress.hpp"

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

ProgressBar::ProgressBar(std::ostream& out, std::int64_t total, std::int64_t already, double delay_seconds)
    : out_(out), total_(total), already_(already), delay_seconds_(delay_seconds),
      start_(std::chrono::steady_clock::now()), done_(already) {}

void ProgressBar::update(std::int64_t done) {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = std::max(done_, done);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    constexpr double redraw_interval = 0.2; // seconds; a terminal needs no more
    if (elapsed < delay_seconds_ ||
        (last_draw_ >= 0 && elapsed - last_draw_ < redraw_interval && done_ < total_))
        return;
    draw(done_, elapsed);
}

void ProgressBar::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!shown_)
        return;
    draw(done_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    out_ << '\n' << std::flush;
    shown_ = false;
}

void ProgressBar::draw(std::int64_t done, double elapsed) {
    constexpr int width = 30;
    const double fraction = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
    const int filled = static_cast<int>(fraction * width);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(width, '.');
    // The ETA extrapolates this session's pace; resumed runs took no time here.
    const std::int64_t done_here = done - already_;
    std::string eta = "--:--";
    if (done_here > 0)
        eta = format_duration(elapsed / static_cast<double>(done_here) * static_cast<double>(total_ - done));
    char line[160];
    std::snprintf(line, sizeof line, "\r[%s] %lld/%lld runs  elapsed %s  eta %s ", bar.c_str(),
                  static_cast<long long>(done), static_cast<long long>(total_),
                  format_duration(elapsed).c_str(), eta.c_str());
    out_ << line << std::flush;
    shown_ = true;
    last_draw_ = elapsed;
}

} // namespace mhb
