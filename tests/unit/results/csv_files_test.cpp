// write_file_atomically and read_whole_file (results/store/csv.hpp): a failure says the OS's reason and
// leaves nothing behind (no .tmp, the old file intact); devices are written in place. The tests
// run as root in CI, where permissions are no obstacle, so failures are provoked by paths the OS
// refuses to anyone (a path under a regular file, a directory, /sys, /dev/full).
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "results/store/csv.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / ("mhb_csv_files_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "no error";
}

TEST(WriteFileAtomically, WritesAndReplacesWholeFiles) {
    const fs::path file = scratch() / "a.txt";
    write_file_atomically(file, "first\n");
    write_file_atomically(file, "second\n");
    EXPECT_EQ(read_whole_file(file), "second\n");
    EXPECT_FALSE(fs::exists(scratch() / "a.txt.tmp"));
}

TEST(WriteFileAtomically, FailuresSayTheOsReasonAndLeaveNoTemporaryFile) {
    const fs::path dir = scratch();
    std::ofstream(dir / "plain") << "x";
    EXPECT_EQ(error_of([&] { write_file_atomically(dir / "plain" / "f.csv", "x"); }),
              (dir / "plain" / "f.csv").string() + ": cannot be written (Not a directory)");
    EXPECT_EQ(error_of([&] { write_file_atomically(dir / "missing" / "f.csv", "x"); }),
              (dir / "missing" / "f.csv").string() + ": cannot be written (No such file or directory)");
    // sysfs refuses new files even to root (Permission denied here, Read-only file system in some
    // containers): the message carries whichever reason the OS gave.
    const std::string sys = error_of([&] { write_file_atomically("/sys/mhb-test.csv", "x"); });
    EXPECT_EQ(sys.rfind("/sys/mhb-test.csv: cannot be written (", 0), 0u) << sys;
    EXPECT_EQ(sys.back(), ')') << sys;
    // The rename fails (a non-empty directory is in the way): the temporary file is removed.
    fs::create_directories(dir / "taken" / "inside");
    EXPECT_NE(error_of([&] { write_file_atomically(dir / "taken", "x"); }).find(": cannot be written ("),
              std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "taken.tmp"));
    EXPECT_TRUE(fs::is_directory(dir / "taken" / "inside"));
}

TEST(WriteFileAtomically, DevicesAreWrittenInPlaceNeverReplaced) {
    EXPECT_EQ(error_of([] { write_file_atomically("/dev/full", "x"); }),
              "/dev/full: cannot be written (No space left on device)");
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
    EXPECT_FALSE(fs::exists("/dev/full.tmp"));
    EXPECT_NO_THROW(write_file_atomically("/dev/null", "x"));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(ReadWholeFile, FailuresSayTheOsReason) {
    EXPECT_EQ(error_of([] { read_whole_file("/no/such/file"); }),
              "/no/such/file: cannot be read (No such file or directory)");
    EXPECT_EQ(error_of([] { read_whole_file("/tmp"); }), "/tmp: cannot be read (Is a directory)");
    const fs::path file = scratch() / "bytes.bin";
    const std::string content("a\0b\nc", 5);
    write_file_atomically(file, content);
    EXPECT_EQ(read_whole_file(file), content);
}

} // namespace
} // namespace mhb
