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

ProgressWork::ProgressWork(std::vector<double> costs, const std::vector<std::int64_t>& runs,
                           const std::set<std::int64_t>& stored)
    : costs_(std::move(costs)), runs_(static_cast<std::int64_t>(runs.size())) {
    for (const std::int64_t id : runs) {
        const double cost = id >= 0 && static_cast<std::size_t>(id) < costs_.size()
                                ? costs_[static_cast<std::size_t>(id)]
                                : 1.0;
        total_ += cost;
        if (stored.count(id) != 0) {
            done_ += cost;
            ++runs_done_;
        }
    }
}

ProgressWork ProgressWork::uniform(std::int64_t runs, std::int64_t stored) {
    std::vector<std::int64_t> ids(static_cast<std::size_t>(std::max<std::int64_t>(runs, 0)));
    std::set<std::int64_t> finished;
    for (std::int64_t i = 0; i < runs; ++i) {
        ids[static_cast<std::size_t>(i)] = i;
        if (i < stored)
            finished.insert(i);
    }
    return ProgressWork(std::vector<double>(ids.size(), 1.0), ids, finished);
}

void ProgressWork::finished(std::int64_t run_id) {
    const double cost = run_id >= 0 && static_cast<std::size_t>(run_id) < costs_.size()
                            ? costs_[static_cast<std::size_t>(run_id)]
                            : 1.0;
    done_ = std::min(total_, done_ + cost);
    done_here_ += cost;
    runs_done_ = std::min(runs_, runs_done_ + 1);
    ++runs_done_here_;
}

double ProgressWork::fraction_done() const {
    return total_ > 0 ? std::min(1.0, done_ / total_) : 1.0;
}

ProgressBar::ProgressBar(std::ostream& out, ProgressWork work, ProgressOptions options,
                         double after_runs_seconds)
    : out_(out), work_(std::move(work)), options_(options), after_runs_seconds_(after_runs_seconds),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(std::int64_t run_id, std::int64_t evaluations) {
    const std::lock_guard<std::mutex> lock(mutex_);
    work_.finished(run_id);
    evaluations_ += static_cast<double>(evaluations);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    // A terminal is redrawn a few times a second (and at the last run); a log gets a line per interval.
    const double interval = options_.terminal ? 0.2 : options_.line_interval;
    const bool due = last_draw_ < 0
                         ? elapsed >= std::max(options_.delay_seconds, options_.terminal ? 0.0 : interval)
                         : elapsed - last_draw_ >= interval;
    const bool last = work_.runs_done() == work_.runs();
    if (elapsed < options_.delay_seconds || !(due || (options_.terminal && shown_ && last)))
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

// "0:21 (runs 0:15, report 0:06)": the runs still to do at this session's pace of work (cost per
// second), then what follows them; "--:--" until a run of this session has finished.
std::string ProgressBar::eta_text(double elapsed) const {
    if (work_.runs_done_here() == 0 || work_.done_here() <= 0)
        return "--:--";
    const double runs = elapsed / work_.done_here() * work_.remaining();
    if (after_runs_seconds_ <= 0)
        return format_duration(runs);
    return format_duration(runs + after_runs_seconds_) + " (runs " + format_duration(runs) + ", report " +
           format_duration(after_runs_seconds_) + ")";
}

void ProgressBar::draw(double elapsed) {
    // Rates extrapolate this session's pace; resumed runs took no time here.
    const double runs_per_second = elapsed > 0 ? static_cast<double>(work_.runs_done_here()) / elapsed : 0.0;
    const double evaluations_per_second = elapsed > 0 ? evaluations_ / elapsed : 0.0;
    const std::string eta = eta_text(elapsed);
    const double fraction = work_.fraction_done();
    const auto done = static_cast<long long>(work_.runs_done());
    const auto total = static_cast<long long>(work_.runs());
    char line[320];
    if (options_.terminal) {
        constexpr int width = 20;
        std::string bar(static_cast<std::size_t>(fraction * width), '#');
        bar.resize(width, '.');
        std::snprintf(line, sizeof line,
                      "\r[%s] %lld/%lld runs %.0f%%  %.3g runs/s  %.3g evals/s  elapsed %s  eta %s ",
                      bar.c_str(), done, total, 100.0 * fraction, runs_per_second, evaluations_per_second,
                      format_duration(elapsed).c_str(), eta.c_str());
    } else {
        std::snprintf(line, sizeof line,
                      "progress: %lld/%lld runs (%.0f%% of the work), %.3g runs/s, %.3g evals/s, elapsed %s, "
                      "eta %s\n",
                      done, total, 100.0 * fraction, runs_per_second, evaluations_per_second,
                      format_duration(elapsed).c_str(), eta.c_str());
    }
    out_ << line << std::flush;
    shown_ = true;
    last_draw_ = elapsed;
}

} // namespace mhb
