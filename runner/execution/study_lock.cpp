#include "runner/execution/study_lock.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

#include "runner/execution/context.hpp"

namespace mhb {
namespace {

std::string system_error(const std::filesystem::path& path, const char* what, int error) {
    return path.string() + ": " + what + " (" + std::strerror(error) + ")";
}

std::string read_all(int fd) {
    std::string text;
    char buf[512];
    for (off_t at = 0;;) {
        const ssize_t got = ::pread(fd, buf, sizeof buf, at);
        if (got <= 0 || text.size() > 4096) // a lock file is a few short lines
            return text;
        text.append(buf, static_cast<std::size_t>(got));
        at += got;
    }
}

// The text of the lock file at `path`, "" when there is none.
std::string read_lock_file(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return "";
    std::string text = read_all(fd);
    ::close(fd);
    return text;
}

// What the holder wrote. A holder that has just taken the lock may not have written it yet:
// give it a moment rather than answer "somebody".
std::string holder_text(const std::filesystem::path& path) {
    std::string text = read_lock_file(path);
    for (int attempt = 0; attempt < 10 && text.find("pid = ") == std::string::npos; ++attempt) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        text = read_lock_file(path);
    }
    return text;
}

// Whether `fd` is still the file at `path`: a holder removes the lock file before releasing it,
// so a lock taken on a file that was removed meanwhile guards nothing.
bool is_file_at(int fd, const std::filesystem::path& path) {
    struct stat opened {};
    struct stat named {};
    return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 && opened.st_dev == named.st_dev &&
           opened.st_ino == named.st_ino;
}

// Errors of flock on a directory that say the filesystem cannot lock one this way (NFS maps flock
// onto fcntl locks, which need write access: EBADF), rather than that someone holds it.
bool cannot_lock_directories(int error) {
    return error == EBADF || error == ENOLCK || error == EOPNOTSUPP || error == EINVAL;
}

// `dir` opened and flocked, or -1 when it cannot be locked so (its filesystem cannot lock a
// directory, or it cannot be opened for reading).
int lock_directory(const std::filesystem::path& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0 && errno == EACCES) // a directory one may write but not list: its lock file will do
        return -1;
    if (fd < 0)
        throw std::runtime_error(system_error(dir, "cannot be opened", errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0)
        return fd;
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK)
        throw StudyInUse(dir.string() + " is in use by " +
                         study_lock_holder(holder_text(dir / StudyLock::file_name)));
    if (cannot_lock_directories(error))
        return -1;
    throw std::runtime_error(system_error(dir, "cannot be locked", error));
}

// The fallback: the lock file at `path` opened and flocked.
int lock_file(const std::filesystem::path& dir, const std::filesystem::path& path) {
    for (;;) {
        const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0)
            throw std::runtime_error(system_error(path, "cannot be made", errno));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            const std::string text = error == EWOULDBLOCK ? holder_text(path) : "";
            ::close(fd);
            if (error == EWOULDBLOCK)
                throw StudyInUse(dir.string() + " is in use by " + study_lock_holder(text));
            throw std::runtime_error(system_error(path, "cannot be locked", error));
        }
        if (is_file_at(fd, path))
            return fd;
        ::close(fd); // its holder removed it between our open and our lock: lock the new one
    }
}

// Replaces the lock file's text (one left by a holder that died names it still) with `text`.
// Returns errno, or 0.
int write_lock_file(const std::filesystem::path& path, int locked_file, const std::string& text) {
    const int fd =
        locked_file >= 0 ? locked_file : ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
        return errno;
    const bool written = ::ftruncate(fd, 0) == 0 &&
                         ::pwrite(fd, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size());
    const int error = written ? 0 : (errno != 0 ? errno : EIO);
    if (fd != locked_file)
        ::close(fd);
    return error;
}

std::string value_of(const std::string& text, const std::string& key) {
    return first_field(text, key).value_or("");
}

} // namespace

std::string study_lock_text(const std::string& command) {
    return "command = " + command + "\npid = " + std::to_string(::getpid()) + "\nhost = " + host_name() +
           "\nsince = " + utc_now("%Y-%m-%d %H:%M:%S UTC") + "\n";
}

std::string study_lock_holder(const std::string& text) {
    const std::string pid = value_of(text, "pid");
    if (pid.empty())
        return "another mhbench process";
    const std::string command = value_of(text, "command");
    return (command.empty() ? std::string("mhbench") : command) + " (pid " + pid + " on host " +
           value_of(text, "host") + ", since " + value_of(text, "since") + ")";
}

StudyLock::StudyLock(const std::filesystem::path& dir, const std::string& command)
    : dir_(dir), path_(dir / file_name) {
    std::error_code ec;
    made_dir_ = std::filesystem::create_directories(dir, ec);
    if (ec)
        throw std::runtime_error(dir.string() + ": cannot create the output directory (" + ec.message() +
                                 ")");
    fd_ = lock_directory(dir);
    on_file_ = fd_ < 0;
    if (on_file_)
        fd_ = lock_file(dir, path_);
    if (const int error = write_lock_file(path_, on_file_ ? fd_ : -1, study_lock_text(command)); error != 0) {
        ::unlink(path_.c_str());
        ::close(fd_);
        throw std::runtime_error(system_error(path_, "cannot be written", error));
    }
}

StudyLock::~StudyLock() {
    // Removed while still locked, so that no one takes a lock on a file, or a directory, about to
    // vanish.
    ::unlink(path_.c_str());
    std::error_code ec;
    if (made_dir_ && std::filesystem::is_empty(dir_, ec))
        std::filesystem::remove(dir_, ec);
    ::close(fd_);
}

} // namespace mhb
