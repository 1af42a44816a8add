// Tests of the flux-map CSV reader (problems/fluxmap/flux_map_csv.cpp): each defect of a file is
// one line naming the file, the line and the column, and a good file reads back as written.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "problems/fluxmap/flux_map.hpp"
#include "problems/problem_registry.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {

// Ten good points (more than the 9 of SyRM), then `tail`.
std::string flux_csv_text(const std::string& tail, const std::string& header_line = "i_d,i_q,psi_d,psi_q") {
    std::string text = header_line + "\n";
    for (int k = 0; k < 10; ++k)
        text += std::to_string(k) + ",1," + std::to_string(0.1 + 0.01 * k) + ",0.2\n";
    return text + tail;
}

std::string flux_csv_error(const std::string& text, Eigen::Index min_points = 9) {
    std::istringstream in(text);
    try {
        (void)fluxmap::read_flux_map_csv(in, "map.csv", min_points);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "no error";
}

TEST(FluxMapCsv, GoodFileReadsInAnyColumnOrder) {
    std::istringstream in("psi_q,i_d,psi_d,i_q\r\n0.5,1,0.25,-2\r\n-0.5,1,0.25,2\r\n");
    const fluxmap::FluxMap map = fluxmap::read_flux_map_csv(in, "map.csv", 2);
    ASSERT_EQ(map.size(), 2);
    EXPECT_EQ(map.i_d[0], 1.0);
    EXPECT_EQ(map.i_q[1], 2.0);
    EXPECT_EQ(map.psi_d[0], 0.25);
    EXPECT_EQ(map.psi_q[1], -0.5);
}

TEST(FluxMapCsv, EachDefectIsOneLineNamingFileLineAndColumn) {
    const std::pair<std::string, std::string> cases[] = {
        {flux_csv_text("", "i_d,i_q,psi_d"),
         "map.csv: line 1, the header has no column 'psi_q' (a flux map has "
         "the columns i_d,i_q,psi_d,psi_q)"},
        {flux_csv_text("1,2,0.3\n"), "map.csv: line 12, column 'psi_q' is missing (the row has 3 fields)"},
        {flux_csv_text("1,2,nan,0.3\n"),
         "map.csv: line 12, column 'psi_d': 'nan' is not finite (NaN or infinity)"},
        {flux_csv_text("1,-inf,0.5,0.3\n"),
         "map.csv: line 12, column 'i_q': '-inf' is not finite (NaN or infinity)"},
        {flux_csv_text("1,abc,0.5,0.3\n"), "map.csv: line 12, column 'i_q': 'abc' is not a number"},
        {flux_csv_text("1,banana,0.5,0.3\n"), "map.csv: line 12, column 'i_q': 'banana' is not a number"},
        {flux_csv_text("1,2,0.5,+Infinity\n"),
         "map.csv: line 12, column 'psi_q': '+Infinity' is not finite (NaN or infinity)"},
        {flux_csv_text("1,,0.5,0.3\n"), "map.csv: line 12, column 'i_q': the field is empty"},
        {flux_csv_text("2e5,1,0.5,0.3\n"), "map.csv: line 12, column 'i_d': 2e5 is outside [-1e5, 1e5] A (a "
                                           "machine's current; larger is damage or mA)"},
        {flux_csv_text("1,1,-1e400,0.5\n"),
         "map.csv: line 12, column 'psi_d': -1e400 is outside [-100, 100] V s (a "
         "machine's flux linkage; larger is damage or mV s)"},
        {flux_csv_text("1,1,0.5,300\n"),
         "map.csv: line 12, column 'psi_q': 300 is outside [-100, 100] V s (a "
         "machine's flux linkage; larger is damage or mV s)"},
        {flux_csv_text("1,1,0,0\n"),
         "map.csv: line 12, columns 'psi_d', 'psi_q': both are 0 (the model's powers of "
         "|psi| need a nonzero flux linkage; zero flux carries no information)"},
        {flux_csv_text("5,5,0.1,0.2\n"),
         "map.csv: line 12, columns 'psi_d', 'psi_q': the point (0.1, 0.2) is "
         "given twice (a duplicate point)"},
        {"",
         "map.csv: the file is empty (a flux map has the header i_d,i_q,psi_d,psi_q and one row per point)"},
    };
    for (const auto& [text, message] : cases)
        EXPECT_EQ(flux_csv_error(text), message);
    EXPECT_EQ(flux_csv_error(flux_csv_text(""), 14),
              "map.csv: has 10 points, fewer than the model's 14 parameters");
}

TEST(FluxMapCsv, DataFileThroughTheRegistryNamesItsPathAndHash) {
    const auto dir = test_support::fresh_temporary_path("fluxmap", "csv");
    std::filesystem::create_directories(dir);
    const std::string good = (dir / "good.csv").string(), bad = (dir / "bad.csv").string();
    std::ofstream(good) << flux_csv_text("");
    std::ofstream(bad) << flux_csv_text("1,2,nan,0.3\n");
    const auto problem = builtin_problems().create("fluxmap:model=syrm,data=" + good);
    ASSERT_EQ(problem->data_files().size(), 1u);
    EXPECT_EQ(problem->data_files()[0].path, good);
    EXPECT_EQ(problem->data_files()[0].sha256.size(), 64u);
    EXPECT_FALSE(problem->known_optimum().has_value());
    try {
        (void)builtin_problems().create("fluxmap:data=" + good); // 10 points < 14 parameters
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), good + ": has 10 points, fewer than the model's 14 parameters");
    }
    try {
        (void)builtin_problems().create("fluxmap:model=syrm,data=" + bad);
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  bad + ": line 12, column 'psi_d': 'nan' is not finite (NaN or infinity)");
    }
}

} // namespace
} // namespace mhb
