// The CEC input data the executable carries: every file is the published original, byte for byte
// (its SHA-256 equals the one recorded beside the official data), and it is parsed as the official
// code reads it (whitespace tokens, composition shifts by line).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <thread>

#include "problems/cec/cec_data.hpp"
#include "problems/core/sha256.hpp"

namespace mhb::cec {
namespace {

TEST(CecData, EveryShippedFileHasTheRecordedSha256OfTheOriginal) {
    for (const Suite suite : {Suite::cec2017, Suite::cec2022}) {
        const auto recorded = recorded_sha256(suite);
        const auto names = data_file_names(suite);
        ASSERT_EQ(names.size(), recorded.size()) << suite_name(suite);
        for (std::size_t i = 0; i < names.size(); ++i) {
            ASSERT_EQ(names[i], recorded[i].first) << suite_name(suite);
            EXPECT_EQ(sha256_hex(data_file_bytes(suite, names[i])), recorded[i].second)
                << suite_name(suite) << ' ' << names[i];
        }
    }
    // As listed in ../shared/cec/README.md: 328 files for 2017, 54 for 2022.
    EXPECT_EQ(data_file_names(Suite::cec2017).size(), 328u);
    EXPECT_EQ(data_file_names(Suite::cec2022).size(), 54u);
}

// When the official folder is beside the repository (as in CI), the shipped bytes equal it too.
TEST(CecData, EqualsTheOfficialFolderWhenPresent) {
    const std::filesystem::path shared = std::filesystem::path(MHB_SOURCE_DIR) / ".." / "shared" / "cec";
    if (!std::filesystem::exists(shared / "SHA256SUMS"))
        GTEST_SKIP() << "no ../shared/cec beside the repository";
    for (const auto& [suite, year] : {std::pair{Suite::cec2017, "2017"}, std::pair{Suite::cec2022, "2022"}})
        for (const auto& name : data_file_names(suite)) {
            std::ifstream in(shared / year / "input_data" / name, std::ios::binary);
            ASSERT_TRUE(in) << name;
            std::ostringstream bytes;
            bytes << in.rdbuf();
            EXPECT_EQ(bytes.str(), data_file_bytes(suite, name)) << year << '/' << name;
        }
}

TEST(CecData, ParsesNumbersWithTheirLines) {
    const auto shift = data_file(Suite::cec2017, "shift_data_1.txt");
    EXPECT_EQ(shift->numbers.size(), 100u);
    EXPECT_EQ(shift->line_starts.size(), 1u);

    const auto matrix = data_file(Suite::cec2017, "M_1_D10.txt");
    EXPECT_EQ(matrix->numbers.size(), 100u);
    EXPECT_EQ(matrix->line_starts.size(), 10u);

    // Composition functions: 10 lines of 100 numbers, o_k = first D numbers of line k.
    const auto composition = data_file(Suite::cec2017, "shift_data_21.txt");
    ASSERT_EQ(composition->line_starts.size(), 10u);
    EXPECT_EQ(composition->numbers.size(), 1000u);
    const auto o2 = composition->line_prefix(2, 10);
    EXPECT_EQ(o2.front(), composition->numbers[200]);
    EXPECT_EQ(o2.back(), composition->numbers[209]);
    EXPECT_THROW((void)composition->line_prefix(10, 10), std::invalid_argument);
    EXPECT_THROW((void)composition->line_prefix(0, 101), std::invalid_argument);
    EXPECT_THROW((void)composition->range(995, 10), std::invalid_argument);

    // CEC 2022's shift_data_8.txt has 10 lines; hybrids read only the first D numbers.
    EXPECT_EQ(data_file(Suite::cec2022, "shift_data_8.txt")->line_starts.size(), 10u);

    // Shuffles are 1-based permutations of 1..D.
    const auto shuffle = data_file(Suite::cec2017, "shuffle_data_11_D10.txt");
    ASSERT_EQ(shuffle->numbers.size(), 10u);
    std::vector<double> sorted = shuffle->numbers;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i)
        EXPECT_EQ(sorted[i], static_cast<double>(i + 1));
}

TEST(CecData, ParsedValuesEqualStrtodOfTheText) {
    const std::string text = data_file_bytes(Suite::cec2022, "M_1_D10.txt");
    std::istringstream in(text);
    const auto parsed = data_file(Suite::cec2022, "M_1_D10.txt");
    std::string token;
    std::size_t i = 0;
    while (in >> token) {
        ASSERT_LT(i, parsed->numbers.size());
        EXPECT_EQ(parsed->numbers[i++], std::strtod(token.c_str(), nullptr)) << token;
    }
    EXPECT_EQ(i, parsed->numbers.size());
}

TEST(CecData, MissingFileNamesSuiteAndFile) {
    EXPECT_FALSE(has_data_file(Suite::cec2017, "shuffle_data_11_D20.txt"));
    EXPECT_TRUE(has_data_file(Suite::cec2017, "shuffle_data_20_D20.txt"));
    try {
        (void)data_file(Suite::cec2017, "shuffle_data_11_D20.txt");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("cec2017"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("shuffle_data_11_D20.txt"), std::string::npos) << e.what();
    }
}

TEST(CecData, OneParsedCopySharedAcrossThreads) {
    std::vector<std::shared_ptr<const DataFile>> seen(4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < seen.size(); ++t)
        threads.emplace_back([&seen, t] { seen[t] = data_file(Suite::cec2017, "M_30_D50.txt"); });
    for (auto& thread : threads)
        thread.join();
    for (const auto& file : seen)
        EXPECT_EQ(file.get(), seen.front().get());
    EXPECT_EQ(seen.front()->numbers.size(), 10u * 50u * 50u);
}

} // namespace
} // namespace mhb::cec
