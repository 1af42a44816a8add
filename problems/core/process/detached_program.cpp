#include "problems/core/process/detached_program.hpp"

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace mhb::process {

void start_detached(const std::vector<std::string>& argv) {
    if (argv.empty())
        return;
    std::vector<std::string> words = argv; // before fork: the child only makes system calls
    std::vector<char*> pointers;
    for (auto& w : words)
        pointers.push_back(w.data());
    pointers.push_back(nullptr);
    const pid_t child = ::fork();
    if (child == 0) {
        ::setsid();
        if (::fork() == 0) {
            const int null = ::open("/dev/null", O_RDWR);
            if (null >= 0) {
                ::dup2(null, STDIN_FILENO);
                ::dup2(null, STDOUT_FILENO);
                ::dup2(null, STDERR_FILENO);
            }
            // mhbench ignores SIGPIPE (runner/cli/main.cpp), and an ignored signal stays ignored
            // across exec.
            struct sigaction by_default {};
            by_default.sa_handler = SIG_DFL;
            sigemptyset(&by_default.sa_mask);
            ::sigaction(SIGPIPE, &by_default, nullptr);
            (void)::close_range(STDERR_FILENO + 1, ~0U, CLOSE_RANGE_CLOEXEC);
            ::execv(pointers[0], pointers.data());
        }
        ::_exit(0);
    }
    if (child > 0)
        while (::waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
        }
}

} // namespace mhb::process
