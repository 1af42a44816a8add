// Tests of the PMSM dataset CSV reader and writer (problems/pmsm/dataset_csv.*): every malformed
// file gives one error naming the file, the line and the column.
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"

namespace mhb::pmsm {
namespace {

// Header on line 2, data rows on lines 3..6 (two in each state).
const std::string good = "# Rs=0.33\n"
                         "t,ud,uq,id,iq,omega\n"
                         "0,-14.5,43.4,0,8.6,523.6\n"
                         "0.0001,-14.5,43.4,0,8.6,523.6\n"
                         "0.0002,-15.1,40.0,-2,8.6,523.6\n"
                         "0.0003,-15.1,40.0,-2,8.6,523.6\n";

std::string csv_error_of(const std::string& text) {
    std::istringstream in(text);
    try {
        (void)read_dataset_csv(in, "drive.csv");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "no error";
}

std::string replace_line(const std::string& text, int line, const std::string& with) {
    std::istringstream in(text);
    std::string out, l;
    for (int n = 1; std::getline(in, l); ++n)
        out += (n == line ? with : l) + "\n";
    return out;
}

TEST(PmsmDatasetCsv, ReadsAGoodFileAndInfersTheState) {
    std::istringstream in(good);
    const Dataset d = read_dataset_csv(in, "drive.csv");
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d.injected, (std::vector<bool>{false, false, true, true}));
    EXPECT_EQ(d.ud[2], -15.1);
    ASSERT_NE(d.find_metadata("Rs"), nullptr);
    EXPECT_EQ(*d.find_metadata("Rs"), "0.33");
    EXPECT_FALSE(d.true_parameters().has_value()); // Ld, Lq, psi missing
}

TEST(PmsmDatasetCsv, ColumnsInAnyOrderWithInjectedColumn) {
    std::istringstream in("omega,t,injected,id,iq,uq,ud\n"
                          "523.6,0,0,0.5,8.6,43.4,-14.5\n"
                          "523.6,0,1,0.5,8.6,43.4,-14.5\n"
                          "523.6,0,0,0.5,8.6,43.4,-14.5\n"
                          "523.6,0,1,0.5,8.6,43.4,-14.5\n");
    const Dataset d = read_dataset_csv(in, "x.csv");
    EXPECT_EQ(d.injected, (std::vector<bool>{false, true, false, true})); // the column wins over |id|
    EXPECT_EQ(d.ud[0], -14.5);
    EXPECT_EQ(d.omega[3], 523.6);
}

TEST(PmsmDatasetCsv, ErrorsNameFileLineAndColumn) {
    EXPECT_EQ(csv_error_of(replace_line(good, 4, "0.0001,-14.5,abc,0,8.6,523.6")),
              "drive.csv: line 4, column 'uq': 'abc' is not a number");
    EXPECT_EQ(csv_error_of(replace_line(good, 5, "0.0002,nan,40.0,-2,8.6,523.6")),
              "drive.csv: line 5, column 'ud': 'nan' is not finite (NaN or infinity)");
    EXPECT_EQ(csv_error_of(replace_line(good, 6, "0.0003,-15.1,40.0,-2,8.6,inf")),
              "drive.csv: line 6, column 'omega': 'inf' is not finite (NaN or infinity)");
    EXPECT_EQ(csv_error_of(replace_line(good, 3, "0,-14.5,43.4,0,8.6")),
              "drive.csv: line 3, row has 5 fields but the header has 6 columns");
    EXPECT_EQ(csv_error_of(replace_line(good, 3, "0,-14.5,,0,8.6,523.6")),
              "drive.csv: line 3, column 'uq': the field is empty");
    EXPECT_EQ(csv_error_of(replace_line(good, 2, "t,ud,uq,id,iq")),
              "drive.csv: line 2, column 'omega' is missing from the header (expected "
              "t,ud,uq,id,iq,omega[,injected])");
    EXPECT_EQ(
        csv_error_of(replace_line(good, 2, "t,ud,uq,id,iq,omega,speed")),
        "drive.csv: line 2, column 7: unknown column 'speed' (expected t,ud,uq,id,iq,omega[,injected])");
    EXPECT_EQ(csv_error_of(replace_line(good, 2, "t,ud,uq,id,iq,omega,ud")),
              "drive.csv: line 2, column 7: column 'ud' appears twice");
    EXPECT_EQ(csv_error_of("t,ud,uq,id,iq,omega,injected\n0,1,2,0,8,500,0\n0,1,2,0,8,500,2\n"),
              "drive.csv: line 3, column 'injected': '2' is not 0 or 1");
    EXPECT_EQ(csv_error_of("t,ud,uq,id,iq,omega\n0,1,2,0,8,500\n0,1,2,-2,8,500\n"),
              "drive.csv: line 3, too few rows: 2 data rows, at least 4 needed");
    // No injected samples: every |id| is below the 1 A threshold.
    EXPECT_EQ(csv_error_of(replace_line(replace_line(good, 5, "0.0002,-15.1,40.0,-0.5,8.6,523.6"), 6,
                                        "0.0003,-15.1,40.0,-0.5,8.6,523.6")),
              "drive.csv: line 6, column 'id': no samples in the injected state (by |id| > 1 A)");
    EXPECT_EQ(
        csv_error_of("t,ud,uq,id,iq,omega,injected\n0,1,2,0,8,500,1\n0,1,2,0,8,500,1\n0,1,2,0,8,500,1\n"
                     "0,1,2,0,8,500,1\n"),
        "drive.csv: line 5, column 'injected': no samples in the id = 0 state (by its 'injected' column)");
    EXPECT_EQ(csv_error_of("# only=metadata\n"),
              "drive.csv: no header line (expected t,ud,uq,id,iq,omega[,injected])");
    EXPECT_EQ(csv_error_of("# Rs=1\n# Rs=2\n" + good.substr(good.find('\n') + 1)),
              "drive.csv: line 2, metadata key 'Rs' is given twice");
}

TEST(PmsmDatasetCsv, MissingFileIsARuntimeError) {
    EXPECT_THROW((void)read_dataset_csv("/nonexistent/drive.csv"), std::runtime_error);
}

// Writing then reading gives the same dataset bit for bit (numbers are written as the shortest
// text that reads back to the same double), including the metadata and the state column.
TEST(PmsmDatasetCsv, WriteThenReadIsExact) {
    SimulatorConfig config;
    config.noise_i = 0.02;
    config.noise_u = 0.5;
    config.samples_per_state = 50;
    const Dataset d = simulate_dataset(config);
    std::stringstream buffer;
    write_dataset_csv(buffer, d);
    const Dataset back = read_dataset_csv(buffer, "buffer");
    EXPECT_EQ(back.t, d.t);
    EXPECT_EQ(back.ud, d.ud);
    EXPECT_EQ(back.uq, d.uq);
    EXPECT_EQ(back.id, d.id);
    EXPECT_EQ(back.iq, d.iq);
    EXPECT_EQ(back.omega, d.omega);
    EXPECT_EQ(back.injected, d.injected);
    EXPECT_EQ(back.metadata, d.metadata);
    ASSERT_TRUE(back.true_parameters().has_value());
    EXPECT_EQ(*back.true_parameters(), config.motor.identified());
}

} // namespace
} // namespace mhb::pmsm
