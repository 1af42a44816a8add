#include "runner/distribution/mpi/mpi_messages.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "results/store/record_codec.hpp"

namespace mhb::mpi {
namespace {

int byte_count(const std::string& bytes) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
        throw std::runtime_error("MPI: a message of " + std::to_string(bytes.size()) +
                                 " bytes is beyond MPI's int counts");
    return static_cast<int>(bytes.size());
}

void expect_end(const ByteReader& in) {
    if (!in.at_end())
        throw std::runtime_error("MPI message: bytes left over after its content");
}

} // namespace

std::optional<Message> receive(int source) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (arrived == 0)
        return std::nullopt;
    int size = 0;
    MPI_Get_count(&status, MPI_BYTE, &size);
    Message message{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(size), '\0')};
    // The probed message itself: only this thread receives, and messages from one source with
    // one tag arrive in the order they were sent.
    MPI_Recv(message.bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return message;
}

void Outbox::send(int destination, Tag tag, std::string bytes) {
    Pending& p = pending_.emplace_back();
    p.bytes = std::move(bytes);
    MPI_Isend(p.bytes.data(), byte_count(p.bytes), MPI_BYTE, destination, tag, MPI_COMM_WORLD, &p.request);
}

void Outbox::progress() {
    for (auto it = pending_.begin(); it != pending_.end();) {
        int sent = 0;
        MPI_Test(&it->request, &sent, MPI_STATUS_IGNORE);
        it = sent != 0 ? pending_.erase(it) : std::next(it);
    }
}

void Outbox::flush() {
    Pace pace;
    for (progress(); !pending_.empty(); progress())
        std::this_thread::sleep_for(pace.next(false));
}

std::chrono::microseconds Pace::next(bool active) {
    interval_ =
        active ? std::chrono::microseconds(50) : std::min(interval_ * 2, std::chrono::microseconds(1000));
    return interval_;
}

std::string encode_count(std::uint64_t count) {
    ByteWriter out;
    out.u64(count);
    return out.take();
}

std::uint64_t decode_count(std::string_view bytes) {
    ByteReader in(bytes, "MPI request");
    const std::uint64_t count = in.u64();
    expect_end(in);
    return count;
}

std::string encode_ids(const std::vector<std::int64_t>& ids) {
    ByteWriter out;
    out.u64(ids.size());
    for (const std::int64_t id : ids)
        out.i64(id);
    return out.take();
}

std::vector<std::int64_t> decode_ids(std::string_view bytes) {
    ByteReader in(bytes, "MPI run list");
    const std::uint64_t n = in.u64();
    if (n > bytes.size() / 8)
        throw std::runtime_error("MPI run list: " + std::to_string(n) + " runs announced in " +
                                 std::to_string(bytes.size()) + " bytes");
    std::vector<std::int64_t> ids(static_cast<std::size_t>(n));
    for (auto& id : ids)
        id = in.i64();
    expect_end(in);
    return ids;
}

std::string encode_outcome(Ending ending, const RunnerOutcome& outcome) {
    ByteWriter out;
    out.u64(static_cast<std::uint64_t>(ending));
    out.i64(outcome.total);
    out.i64(outcome.resumed);
    out.i64(outcome.kept);
    out.u64(outcome.interrupted ? 1 : 0);
    return out.take();
}

Ending decode_outcome(std::string_view bytes, RunnerOutcome& outcome) {
    ByteReader in(bytes, "MPI outcome");
    const std::uint64_t ending = in.u64();
    if (ending > static_cast<std::uint64_t>(Ending::cancelled))
        throw std::runtime_error("MPI outcome: unknown ending " + std::to_string(ending));
    outcome.total = in.i64();
    outcome.resumed = in.i64();
    outcome.kept = in.i64();
    outcome.interrupted = in.u64() != 0;
    expect_end(in);
    return static_cast<Ending>(ending);
}

void abort_job(const char* what) {
    int rank = -1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    std::cerr << "mhbench: MPI rank " << rank << ": " << what << "; ending every rank\n" << std::flush;
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::abort(); // MPI_Abort does not return
}

} // namespace mhb::mpi
