#include "problems/external/child_link.hpp"

#include "problems/external/command.hpp"

namespace mhb::external {
namespace {

constexpr std::size_t max_line = 64 << 20; // a reply longer than this is garbage, not data

} // namespace

ChildLink::ChildLink(const std::vector<std::string>& argv) : program_(program_name(argv)) {
    try {
        child_.emplace(argv, process::ChildOptions{.input = process::Stream::pipe,
                                                   .output = process::Stream::pipe,
                                                   .errors = process::Stream::tail});
    } catch (const process::SpawnError& e) {
        throw ChildFault(e.what(), {});
    }
}

void ChildLink::kill() {
    child_->end();
}

void ChildLink::finish(std::chrono::duration<double> grace) {
    child_->close_input();
    child_->wait_for_exit(std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(grace));
    kill();
}

void ChildLink::send(const std::string& line) {
    if (!child_->input_open())
        throw ChildFault(program_ + " " + child_->exit_description("closed its output"), stderr_tail());
    bool written = false;
    try {
        written = child_->write_input(line + '\n');
    } catch (const std::runtime_error& e) {
        throw ChildFault(program_ + ": " + e.what(), stderr_tail());
    }
    if (!written) // no reader left: it exited (or closed its stdin) before reading all it was sent
        throw ChildFault(program_ + " " + child_->exit_description("closed its stdin") +
                             " before reading all it was sent",
                         stderr_tail());
}

std::string ChildLink::receive(std::chrono::duration<double> timeout) {
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(timeout);
    for (;;) {
        if (const auto newline = out_buffer_.find('\n'); newline != std::string::npos) {
            std::string line = out_buffer_.substr(0, newline);
            out_buffer_.erase(0, newline + 1);
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            return line;
        }
        if (out_buffer_.size() > max_line)
            throw ChildFault(program_ + " wrote a line longer than 64 MiB", stderr_tail());
        process::ChildProcess::Read read = process::ChildProcess::Read::end;
        try {
            read = child_->read_output(out_buffer_, deadline);
        } catch (const std::runtime_error& e) {
            throw ChildFault(e.what(), stderr_tail());
        }
        if (read == process::ChildProcess::Read::timeout)
            throw ChildFault(program_ + " did not answer within " +
                                 std::to_string(std::chrono::duration<double>(timeout).count()) + " s",
                             stderr_tail());
        if (read == process::ChildProcess::Read::end) {
            if (!out_buffer_.empty() && out_buffer_.find('\n') == std::string::npos)
                out_buffer_ += '\n'; // a last line without its newline is still read as one
            else if (out_buffer_.empty())
                throw ChildFault(program_ + " " + child_->exit_description("closed its output"),
                                 stderr_tail());
        }
    }
}

} // namespace mhb::external
