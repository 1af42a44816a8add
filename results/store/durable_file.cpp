#include "results/store/durable_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace mhb {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, int error) {
    throw std::runtime_error(path.string() + ": cannot be synced to disk (" + std::strerror(error) + ")");
}

// Syncs `path` opened with `flags`; a read-only descriptor is enough for fsync on Linux.
void sync_path(const std::filesystem::path& path, int flags) {
    if (!syncs_enabled())
        return;
    const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0)
        fail(path, errno);
    const int result = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (result != 0)
        fail(path, error);
}

} // namespace

bool syncs_enabled() {
    static const bool enabled = [] {
        const char* value = std::getenv("MHBENCH_UNSAFE_NO_FSYNC");
        return value == nullptr || std::string(value) != "1";
    }();
    return enabled;
}

void sync_file(int fd, const std::filesystem::path& path) {
    if (syncs_enabled() && ::fdatasync(fd) != 0)
        fail(path, errno);
}

void start_writeback(int fd) {
    if (syncs_enabled())
        (void)::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE); // a hint: an error shows at the sync
}

void sync_directory(const std::filesystem::path& dir) {
    sync_path(dir.empty() ? std::filesystem::path(".") : dir, O_RDONLY | O_DIRECTORY);
}

} // namespace mhb
