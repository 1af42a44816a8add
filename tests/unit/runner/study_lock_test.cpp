// runner/execution/study_lock.hpp: one holder at a time, the file names it, a second taker is refused with
// the holder's pid and touches nothing (even when the file was deleted), and a lock whose holder died
// (kill -9) is taken over.
#include <csignal>
#include <filesystem>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "runner/execution/study_lock.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

TEST(StudyLock, TheLockFileNamesItsHolderAndGoesWithIt) {
    const fs::path dir = test_support::fresh_temporary_path("mhb_lock_", "names");
    {
        const StudyLock lock(dir, "mhbench run");
        const std::string text = test_support::read_text(dir / StudyLock::file_name);
        EXPECT_NE(text.find("command = mhbench run\n"), std::string::npos) << text;
        EXPECT_NE(text.find("pid = " + std::to_string(::getpid()) + "\n"), std::string::npos) << text;
        EXPECT_NE(text.find("host = "), std::string::npos) << text;
        EXPECT_NE(text.find(" UTC\n"), std::string::npos) << text;
    }
    EXPECT_FALSE(fs::exists(dir)) << "the lock made the directory, and nothing else was put there";
}

TEST(StudyLock, ASecondTakerIsRefusedWithTheHoldersPidAndChangesNothing) {
    const fs::path dir = test_support::fresh_temporary_path("mhb_lock_", "second");
    fs::create_directories(dir);
    const StudyLock first(dir, "mhbench run");
    const std::string before = test_support::read_text(dir / StudyLock::file_name);
    try {
        const StudyLock second(dir, "mhbench merge");
        ADD_FAILURE() << "two holders";
    } catch (const StudyInUse& e) {
        const std::string expected =
            dir.string() + " is in use by mhbench run (pid " + std::to_string(::getpid()) + " on host ";
        EXPECT_EQ(std::string(e.what()).rfind(expected, 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find(", since "), std::string::npos) << e.what();
    }
    EXPECT_EQ(test_support::read_text(dir / StudyLock::file_name), before);
    EXPECT_TRUE(fs::exists(dir)) << "a refused taker removes nothing";
}

// Issue 34: the lock is on the directory, so deleting the file that names the holder lets no
// second writer in; the refusal then names nobody, and the refused taker writes no file.
TEST(StudyLock, DeletingTheLockFileLetsNoSecondTakerIn) {
    const fs::path dir = test_support::fresh_temporary_path("mhb_lock_", "deleted");
    fs::create_directories(dir);
    const StudyLock first(dir, "mhbench run");
    ASSERT_TRUE(fs::remove(dir / StudyLock::file_name));
    try {
        const StudyLock second(dir, "mhbench run");
        ADD_FAILURE() << "two holders";
    } catch (const StudyInUse& e) {
        EXPECT_EQ(std::string(e.what()), dir.string() + " is in use by another mhbench process");
    }
    EXPECT_FALSE(fs::exists(dir / StudyLock::file_name)) << "a refused taker writes nothing";
}

TEST(StudyLock, TheLockOfAProcessKilledWithSigkillIsTakenOver) {
    const fs::path dir = test_support::fresh_temporary_path("mhb_lock_", "stale");
    fs::create_directories(dir);
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) { // holds the lock until killed
        const StudyLock lock(dir, "mhbench run");
        (void)!::write(ready[1], "x", 1);
        ::pause();
        ::_exit(0);
    }
    char byte = 0;
    ASSERT_EQ(::read(ready[0], &byte, 1), 1);
    EXPECT_THROW(StudyLock(dir, "mhbench run"), StudyInUse) << "held by the child";
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    ::close(ready[0]);
    ::close(ready[1]);
    ASSERT_TRUE(fs::exists(dir / StudyLock::file_name)) << "a killed holder leaves its file";
    const StudyLock taken(dir, "mhbench run");
    EXPECT_NE(test_support::read_text(dir / StudyLock::file_name).find("pid = " + std::to_string(::getpid())),
              std::string::npos);
}

TEST(StudyLock, TheHolderIsReadFromTheFile) {
    EXPECT_EQ(study_lock_holder(
                  "command = mhbench merge\npid = 77\nhost = node3\nsince = 2026-11-26 07:55:01 UTC\n"),
              "mhbench merge (pid 77 on host node3, since 2026-11-26 07:55:01 UTC)");
    EXPECT_EQ(study_lock_holder(""), "another mhbench process");
    EXPECT_EQ(study_lock_holder(study_lock_text("mhbench report")).rfind("mhbench report (pid ", 0), 0u);
}

} // namespace
} // namespace mhb
