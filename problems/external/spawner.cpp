#include "problems/external/spawner.hpp"

#include <exception>

namespace mhb::external {

Spawner::Spawner() {
    thread_ = std::thread([this] {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            changed_.wait(lock, [this] { return stopping_ || job_; });
            if (stopping_)
                return;
            job_();
            job_ = nullptr;
            changed_.notify_all();
        }
    });
}

Spawner::~Spawner() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

std::unique_ptr<ChildLink> Spawner::start(const std::vector<std::string>& argv) {
    std::unique_ptr<ChildLink> link;
    std::exception_ptr error;
    bool done = false;
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !job_; });
    job_ = [&] {
        try {
            link = std::make_unique<ChildLink>(argv);
        } catch (...) {
            error = std::current_exception();
        }
        done = true;
    };
    changed_.notify_all();
    changed_.wait(lock, [&] { return done; });
    if (error)
        std::rethrow_exception(error);
    return link;
}

} // namespace mhb::external
