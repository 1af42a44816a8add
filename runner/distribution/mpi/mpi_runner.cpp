#include "runner/distribution/mpi/mpi_runner.hpp"

#include <algorithm>
#include <deque>
#include <exception>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "results/store/record_codec.hpp"
#include "results/store/study_writer.hpp"
#include "runner/distribution/mpi/local_runs.hpp"
#include "runner/distribution/mpi/mpi_messages.hpp"
#include "runner/distribution/shards.hpp"

namespace mhb {
namespace {

// Long runs first, so that none starts last and keeps the other ranks waiting at the end.
void most_expensive_first(const PreparedStudy& study, std::vector<std::int64_t>& ids) {
    if (ids.empty())
        return;
    const std::vector<double> cost = estimated_run_costs(study);
    std::stable_sort(ids.begin(), ids.end(), [&](std::int64_t a, std::int64_t b) {
        return cost[static_cast<std::size_t>(a)] > cost[static_cast<std::size_t>(b)];
    });
}

// Rank 0: hands the runs out, executes its share, journals every record, ends the study.
class Coordinator {
public:
    Coordinator(const PreparedStudy& study, StudyWriter& writer, const RunnerOptions& options, int ranks,
                int threads, DistributedStats* stats)
        : study_(study), writer_(writer), options_(options), ranks_(static_cast<std::size_t>(ranks)),
          local_(study, threads), stats_(stats) {
        if (stats_ != nullptr)
            stats_->runs_by_rank.assign(ranks_.size(), 0);
    }

    // Errors of the study (a write that fails, a run id beyond the study) end it on every rank
    // and are rethrown here once the other ranks know.
    RunnerOutcome run() {
        try {
            order_ = pending_runs(study_, writer_, options_, outcome_);
            most_expensive_first(study_, order_);
        } catch (...) { // told to the other ranks once they have asked for runs, then rethrown
            error_ = std::current_exception();
            order_.clear();
        }
        position_.assign(static_cast<std::size_t>(study_.run_count()), 0);
        for (std::size_t i = 0; i < order_.size(); ++i) {
            position_[static_cast<std::size_t>(order_[i])] = i;
            queue_.insert(i);
        }
        kept_ = outcome_.resumed;
        try {
            exchange();
        } catch (const std::exception& e) { // the exchange is broken: only ending the job avoids a hang
            mpi::abort_job(e.what());
        }
        outcome_.kept = kept_;
        outcome_.interrupted = kept_ < outcome_.total;
        if (!error_ && !outcome_.interrupted && options_.finish_writer) {
            try {
                writer_.finish();
            } catch (...) {
                error_ = std::current_exception();
            }
        }
        for (std::size_t r = 1; r < ranks_.size(); ++r)
            out_.send(static_cast<int>(r), mpi::outcome,
                      mpi::encode_outcome(error_ ? mpi::Ending::failed : mpi::Ending::finished, outcome_));
        out_.flush();
        if (error_)
            std::rethrow_exception(error_);
        return outcome_;
    }

private:
    struct Rank {
        std::set<std::int64_t> held; // handed out, not yet back
        bool done = false;           // it said nothing more will come
        bool stop_sent = false;
    };

    bool stopping() const { return error_ || (options_.stop != nullptr && options_.stop->load()); }

    std::int64_t next_run() {
        const std::size_t first = *queue_.begin();
        queue_.erase(queue_.begin());
        return order_[first];
    }

    void journal(int rank, const RunRecord& record, double wall_seconds) {
        if (stats_ != nullptr)
            ++stats_->runs_by_rank[static_cast<std::size_t>(rank)];
        if (error_)
            return; // after an error, records are dropped: a resume does those runs again
        try {
            writer_.append(record, wall_seconds);
            ++kept_;
            if (options_.on_run_finished)
                options_.on_run_finished(kept_, outcome_.total, record);
        } catch (...) {
            error_ = std::current_exception();
        }
    }

    void handle(const mpi::Message& message) {
        if (message.source <= 0 || static_cast<std::size_t>(message.source) >= ranks_.size())
            throw std::logic_error("message from unknown rank " + std::to_string(message.source));
        Rank& from = ranks_[static_cast<std::size_t>(message.source)];
        switch (message.tag) {
        case mpi::request: {
            const std::uint64_t wanted = mpi::decode_count(message.bytes);
            std::vector<std::int64_t> ids;
            while (!stopping() && ids.size() < wanted && !queue_.empty()) {
                ids.push_back(next_run());
                from.held.insert(ids.back());
            }
            out_.send(message.source, mpi::assign, mpi::encode_ids(ids));
            break;
        }
        case mpi::result: {
            const DecodedRecord decoded = decode_record(message.bytes);
            if (from.held.erase(decoded.record.run_id) == 0)
                throw std::logic_error("rank " + std::to_string(message.source) + " sent run " +
                                       std::to_string(decoded.record.run_id) + ", which it did not hold");
            journal(message.source, decoded.record, decoded.wall_seconds);
            break;
        }
        case mpi::release:
            for (const std::int64_t id : mpi::decode_ids(message.bytes)) {
                if (from.held.erase(id) == 0)
                    throw std::logic_error("rank " + std::to_string(message.source) + " gave back run " +
                                           std::to_string(id) + ", which it did not hold");
                queue_.insert(position_[static_cast<std::size_t>(id)]); // at its place in the order
            }
            break;
        case mpi::done:
            if (!from.held.empty())
                throw std::logic_error("rank " + std::to_string(message.source) + " ended holding " +
                                       std::to_string(from.held.size()) + " runs");
            from.done = true;
            break;
        default:
            throw std::logic_error("unexpected message tag " + std::to_string(message.tag));
        }
    }

    bool finished() const {
        const bool nothing_to_start = stopping() || queue_.empty();
        return nothing_to_start && local_.idle() &&
               std::all_of(ranks_.begin() + 1, ranks_.end(), [](const Rank& r) { return r.done; });
    }

    void exchange() {
        mpi::Pace pace;
        while (!finished()) {
            bool active = false;
            if (stopping())
                for (std::size_t r = 1; r < ranks_.size(); ++r)
                    if (!ranks_[r].done && !ranks_[r].stop_sent) {
                        out_.send(static_cast<int>(r), mpi::stop, {});
                        ranks_[r].stop_sent = true;
                    }
            for (; !stopping() && local_.running() < local_.threads() && !queue_.empty(); active = true)
                local_.start(next_run());
            for (FinishedRun& run : local_.take_finished()) {
                active = true;
                if (run.error) {
                    if (!error_)
                        error_ = run.error;
                } else {
                    journal(0, run.record, run.wall_seconds);
                }
            }
            while (const auto message = mpi::receive(MPI_ANY_SOURCE)) {
                active = true;
                handle(*message);
            }
            out_.progress();
            if (!finished())
                local_.wait(pace.next(active));
        }
    }

    const PreparedStudy& study_;
    StudyWriter& writer_;
    const RunnerOptions& options_;
    std::vector<Rank> ranks_; // by rank; [0] unused
    LocalRuns local_;
    mpi::Outbox out_;
    RunnerOutcome outcome_;
    std::exception_ptr error_;        // the first error: the study stops, every rank is told, it is rethrown
    std::vector<std::int64_t> order_; // the runs to do, most expensive first
    std::vector<std::size_t> position_; // of each run id in order_
    std::set<std::size_t> queue_; // positions in order_ not handed out: a run given back keeps its place
    std::int64_t kept_ = 0;
    DistributedStats* stats_;
};

// Any other rank: executes the runs rank 0 hands it and sends each record back, until rank 0
// sends the study's outcome, which it returns (the message's bytes).
std::string work_for_rank_zero(const PreparedStudy& study, const RunnerOptions& options, int threads) {
    LocalRuns local(study, threads);
    const auto slots = static_cast<std::size_t>(threads);
    mpi::Outbox out;
    mpi::Pace pace;
    std::deque<std::int64_t> waiting; // handed to this rank, not started
    bool asking = false;              // a request is unanswered
    bool closed = false;              // no more requests: rank 0 has no more runs, or this rank stops
    bool stopping = false;
    bool done_sent = false;
    for (;;) {
        bool active = false;
        stopping = stopping || (options.stop != nullptr && options.stop->load());
        for (; !stopping && local.running() < threads && !waiting.empty(); active = true) {
            local.start(waiting.front());
            waiting.pop_front();
        }
        for (FinishedRun& run : local.take_finished()) {
            active = true;
            if (run.error)
                std::rethrow_exception(run.error);
            out.send(0, mpi::result, encode_record(run.record, run.wall_seconds));
        }
        while (auto message = mpi::receive(0)) {
            active = true;
            if (message->tag == mpi::assign) {
                const std::vector<std::int64_t> ids = mpi::decode_ids(message->bytes);
                asking = false;
                closed = closed || ids.empty();
                waiting.insert(waiting.end(), ids.begin(), ids.end());
            } else if (message->tag == mpi::stop) {
                stopping = true;
            } else if (message->tag == mpi::outcome) {
                // Rank 0 sends it once every rank is done, or before the study when it cancels.
                out.flush();
                return std::move(message->bytes);
            } else {
                throw std::logic_error("unexpected message tag " + std::to_string(message->tag));
            }
        }
        if (stopping && !done_sent && (!closed || !waiting.empty())) {
            out.send(0, mpi::release, mpi::encode_ids({waiting.begin(), waiting.end()}));
            waiting.clear();
            closed = true;
            active = true;
        }
        const std::size_t held = static_cast<std::size_t>(local.running()) + waiting.size();
        if (!closed && !asking && held <= slots) {
            out.send(0, mpi::request, mpi::encode_count(2 * slots - held));
            asking = true;
            active = true;
        }
        if (closed && !asking && !done_sent && waiting.empty() && local.idle()) {
            out.send(0, mpi::done, {});
            done_sent = true;
        }
        out.progress();
        local.wait(pace.next(active));
    }
}

RunnerOutcome serve(const PreparedStudy& study, const RunnerOptions& options, int threads) {
    std::string ending;
    try {
        ending = work_for_rank_zero(study, options, threads);
    } catch (const std::exception& e) { // the exchange is broken: only ending the job avoids a hang
        mpi::abort_job(e.what());
    }
    RunnerOutcome outcome;
    switch (mpi::decode_outcome(ending, outcome)) {
    case mpi::Ending::finished:
        return outcome;
    case mpi::Ending::failed:
        throw std::runtime_error("MPI rank 0 stopped the study on an error (its message says which)");
    case mpi::Ending::cancelled:
        break;
    }
    throw std::runtime_error("MPI rank 0 ended before running the study (its message says why)");
}

} // namespace

RunnerOutcome run_study_distributed(const PreparedStudy& study, StudyWriter* writer,
                                    const RunnerOptions& options, const MpiSession& session,
                                    DistributedStats* stats) {
    if ((session.rank() == 0) !=
        (writer != nullptr)) // a misuse; throwing would leave the other ranks waiting
        mpi::abort_job(writer != nullptr ? "run_study_distributed: a StudyWriter on a rank other than 0"
                                         : "run_study_distributed: no StudyWriter on rank 0, the writer");
    // Every rank reads the same options: a bad thread count throws on all of them alike.
    const int threads = resolve_thread_count(options.threads);
    if (session.rank() == 0)
        return Coordinator(study, *writer, options, session.size(), threads, stats).run();
    return serve(study, options, threads);
}

void release_waiting_ranks(const MpiSession& session) {
    if (session.rank() != 0)
        return;
    mpi::Outbox out;
    for (int r = 1; r < session.size(); ++r) {
        // Each rank starts with a request, or, stopped at once, gives back nothing and is done.
        mpi::Pace pace;
        for (;;) {
            const auto message = mpi::receive(r);
            if (message && (message->tag == mpi::request || message->tag == mpi::done))
                break;
            if (!message)
                std::this_thread::sleep_for(pace.next(false));
        }
        out.send(r, mpi::outcome, mpi::encode_outcome(mpi::Ending::cancelled, RunnerOutcome{}));
    }
    out.flush();
}

} // namespace mhb
