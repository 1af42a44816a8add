// Starts child processes from one thread that lives as long as the Spawner. A child's
// PR_SET_PDEATHSIG fires when the *thread* that forked it ends, not the process: children that
// outlive the call that started them (a problem's worker pool, used from the runner's oneTBB
// threads, which come and go) must be forked from a thread that stays.
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "problems/external/child_link.hpp"

namespace mhb::external {

class Spawner {
public:
    Spawner();
    ~Spawner();
    Spawner(const Spawner&) = delete;
    Spawner& operator=(const Spawner&) = delete;

    // ChildLink(argv), constructed on the spawner's thread; rethrows what that throws.
    std::unique_ptr<ChildLink> start(const std::vector<std::string>& argv);

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::function<void()> job_; // at most one at a time
    bool stopping_ = false;
    std::thread thread_;
};

} // namespace mhb::external
