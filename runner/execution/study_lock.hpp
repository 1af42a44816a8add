// One writer per study directory: an advisory lock (flock(2)) on the directory DIR itself, held by
// `mhbench run`, `mhbench merge` (on its output) and `mhbench report` when it writes into the
// study, for as long as they write. DIR/.mhbench.lock is only the text naming the holder (command,
// pid, host, since) for the refusal: deleting it defeats nothing, since the lock is on DIR. A
// second process is refused at once, with a line naming the holder ("another mhbench process" when
// the file is gone), and touches nothing.
//
// The kernel drops a flock when its holder dies, even by kill -9: the file a dead holder leaves
// behind names it but locks nothing, and the next writer takes it over. Where a directory cannot
// be flocked (NFS: Linux maps flock onto fcntl locks, which need a file open for writing) or
// opened for reading (write and search permission only), the lock falls back to a flock of
// DIR/.mhbench.lock itself, as mhbench did before: it works across machines, but deleting the
// file while a study runs lets a second writer in.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "results/store/study_files.hpp"

namespace mhb {

// Another process holds the study's lock. what() is "DIR is in use by mhbench run (pid 1234 on
// host x, since 2026-11-26 07:55:01 UTC)"; the command adds what the user can do about it.
class StudyInUse : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class StudyLock {
public:
    static constexpr const char* file_name = StudyFiles::lock;

    // Takes the lock of `dir` (made if missing) for `command` ("mhbench run"), without waiting.
    // Throws StudyInUse when another process holds it, std::runtime_error when the directory
    // cannot be locked or the lock file cannot be written (a read-only directory, say).
    StudyLock(const std::filesystem::path& dir, const std::string& command);
    // Removes the lock file, then releases the lock (and the directory, when this lock made it
    // and nothing else was put there).
    ~StudyLock();
    StudyLock(const StudyLock&) = delete;
    StudyLock& operator=(const StudyLock&) = delete;

private:
    std::filesystem::path dir_;
    std::filesystem::path path_;
    int fd_ = -1;          // what is locked: the directory, or where it cannot be, the lock file
    bool on_file_ = false; // the fallback: fd_ is the lock file
    bool made_dir_ = false;
};

// "command = ...\npid = ...\nhost = ...\nsince = ... UTC\n": what the lock file of this process
// says about it.
std::string study_lock_text(const std::string& command);

// "mhbench run (pid 1234 on host x, since 2026-11-26 07:55:01 UTC)" from a lock file's text;
// "another mhbench process" when the text names nobody (its holder has not written it yet).
std::string study_lock_holder(const std::string& text);

} // namespace mhb
