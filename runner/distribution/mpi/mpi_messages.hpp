// The messages of the distributed runner (runner/distribution/mpi/mpi_runner.hpp) and the non-blocking way
// they are sent and received. Every payload is bytes in the record codec's format
// (results/store/record_codec.hpp), so a record crosses exactly and malformed bytes throw.
//
//   from another rank to rank 0        from rank 0 to another rank
//   request  u64 runs wanted           assign   the run ids given (none: no more runs, ever)
//   result   one record + wall seconds stop     rank 0 is stopping: give back unstarted runs
//   release  run ids given back        outcome  the study's end: status and RunnerOutcome
//   done     nothing more will come
#pragma once

#include <chrono>
#include <cstdint>
#include <list>
#include <mpi.h>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runner/execution/parallel_runner.hpp"

namespace mhb::mpi {

enum Tag : int { request = 1, result, release, done, assign, stop, outcome };

// How the study ended, as the outcome message tells the other ranks.
enum class Ending : std::uint64_t {
    finished = 0, // the outcome says whether all runs were done
    failed = 1,   // rank 0 met an error (its message says which)
    cancelled = 2 // rank 0 ended before it ran the study
};

struct Message {
    int source = 0;
    int tag = 0;
    std::string bytes;
};

// The next message from `source` (or MPI_ANY_SOURCE), if one has arrived; never waits.
std::optional<Message> receive(int source);

// Sends without blocking: each message keeps its bytes until MPI is done with them.
class Outbox {
public:
    Outbox() = default;
    Outbox(const Outbox&) = delete;
    Outbox& operator=(const Outbox&) = delete;
    void send(int destination, Tag tag, std::string bytes);
    void progress(); // forgets the messages MPI has sent
    void flush();    // returns when every message has been sent

private:
    struct Pending {
        std::string bytes;
        MPI_Request request = MPI_REQUEST_NULL;
    };
    std::list<Pending> pending_; // a list: the bytes never move while MPI reads them
};

// How long a communication loop sleeps: 50 us after something happened, doubling while nothing
// does, up to 1 ms. A waiting rank then costs no core, and answers within about a millisecond.
class Pace {
public:
    std::chrono::microseconds next(bool active);

private:
    std::chrono::microseconds interval_{50};
};

std::string encode_count(std::uint64_t count);
std::uint64_t decode_count(std::string_view bytes);
std::string encode_ids(const std::vector<std::int64_t>& ids);
std::vector<std::int64_t> decode_ids(std::string_view bytes);
std::string encode_outcome(Ending ending, const RunnerOutcome& outcome);
Ending decode_outcome(std::string_view bytes, RunnerOutcome& outcome);

// Ends every rank of the job after printing `what`: a rank that leaves the exchange half-way
// would leave the others waiting for it forever. mpirun then exits non-zero.
[[noreturn]] void abort_job(const char* what);

} // namespace mhb::mpi
