// Making writes survive a power cut or a crash of the machine (not only of the process): a file's
// data reaches the disk with fsync, and a rename (a new directory entry) only with an fsync of its
// directory.
#pragma once

#include <filesystem>

namespace mhb {

// False only when the environment sets MHBENCH_UNSAFE_NO_FSYNC=1: for measuring what the syncs
// cost (BENCHMARKS.md), never for studies one means to keep.
bool syncs_enabled();

// fdatasync of an open file; throws std::runtime_error naming `path` when the disk reports an error.
void sync_file(int fd, const std::filesystem::path& path);
// fsync of a directory, so that the renames and creations in it are on disk.
void sync_directory(const std::filesystem::path& dir);
// Starts writing the file's dirty pages to disk without waiting for them, so that the sync at the
// end finds little left to write (the disk works while the program computes).
void start_writeback(int fd);

} // namespace mhb
