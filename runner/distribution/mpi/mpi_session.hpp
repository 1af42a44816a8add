// MPI for the length of a process: initialised with MPI_THREAD_FUNNELED (only the thread that
// created the session calls MPI; oneTBB's threads never do) and finalised by the destructor.
// Only compiled with MHB_WITH_MPI; runner/distribution/distributed.hpp decides whether to start one.
#pragma once

namespace mhb {

class MpiSession {
public:
    // Throws std::runtime_error when MPI cannot give the FUNNELED thread level.
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    [[nodiscard]] int rank() const { return rank_; }
    [[nodiscard]] int size() const { return size_; }
    // Collective: rank 0's `flag` on every rank.
    [[nodiscard]] bool broadcast(bool flag) const;

private:
    int rank_ = 0;
    int size_ = 1;
};

} // namespace mhb
