// Internal to the study writer (study_writer*.cpp, study_rendering.cpp), not for other code:
// StoreReader, which reads store.bin's payloads back by position, both when a writer opens an
// existing store and when finish() renders the result files from it.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace mhb {

// Reads payloads back by position (pread: no shared file offset, no stream buffer to refill for
// each run). The store is not mapped into memory, so that resident memory stays small.
class StoreReader {
public:
    explicit StoreReader(const std::filesystem::path& path)
        : path_(path), fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
        if (fd_ < 0)
            throw std::runtime_error(path.string() + ": cannot be read (" + std::strerror(errno) + ")");
    }
    ~StoreReader() { ::close(fd_); }
    StoreReader(const StoreReader&) = delete;
    StoreReader& operator=(const StoreReader&) = delete;

    void read(std::uint64_t offset, std::uint64_t size, std::string& payload) const {
        payload.resize(static_cast<std::size_t>(size));
        std::size_t done = 0;
        while (done < payload.size()) {
            const ssize_t n =
                ::pread(fd_, payload.data() + done, payload.size() - done, static_cast<off_t>(offset + done));
            if (n <= 0)
                throw std::runtime_error(
                    path_.string() + ": cannot read a stored run back (" +
                    (n < 0 ? std::strerror(errno) : "the file is shorter than its index") + ")");
            done += static_cast<std::size_t>(n);
        }
    }

private:
    std::filesystem::path path_;
    int fd_;
};

} // namespace mhb
