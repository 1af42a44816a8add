// Inputs read defensively (issue 9): user text quoted to at most 40 characters, integers too
// large named with their maximum, a UTF-8 byte-order mark accepted in a dataset, dataset values
// kept within +-1e9, and least squares that never return a non-finite estimate.
#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>
#include <string>

#include "problems/core/parameters.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/least_squares.hpp"
#include "problems/pmsm/steady_state_data.hpp"

namespace mhb {
namespace {

TEST(TextExcerpt, ShortTextIsQuotedWholeAndLongTextIsCutWithItsLength) {
    EXPECT_EQ(quoted_excerpt("abc"), "'abc'");
    EXPECT_EQ(quoted_excerpt(std::string(40, 'x')), "'" + std::string(40, 'x') + "'");
    EXPECT_EQ(quoted_excerpt("1.0e" + std::string(1048572, '0')),
              "'1.0e000000000000000000000000000000000...' (1048576 characters)");
    EXPECT_EQ(quoted_excerpt(std::string(41, 'y')), "'" + std::string(37, 'y') + "...' (41 characters)");
}

TEST(TextExcerpt, ControlBytesAreVisibleAndUtf8IsNeverSplit) {
    EXPECT_EQ(quoted_excerpt("a\tb\x01"), "'a\\x09b\\x01'");
    // 50 two-byte characters: cut after 37 characters, 74 bytes, on a character boundary.
    std::string accents;
    for (int i = 0; i < 50; ++i)
        accents += "\xC3\xA9";
    std::string expected;
    for (int i = 0; i < 37; ++i)
        expected += "\xC3\xA9";
    EXPECT_EQ(quoted_excerpt(accents), "'" + expected + "...' (50 characters)");
}

TEST(TextExcerpt, ValueExcerptLeavesShortPlainValuesUnquoted) {
    EXPECT_EQ(value_excerpt("many"), "many");
    EXPECT_EQ(value_excerpt("a b"), "a b");
    EXPECT_EQ(value_excerpt("tab\there"), "'tab\\x09here'");
    EXPECT_EQ(value_excerpt(std::string(100, '1')), "'" + std::string(37, '1') + "...' (100 characters)");
}

TEST(IntegerRefusal, SaysTooLargeOrTooSmallWithTheDeclaredLimit) {
    EXPECT_EQ(integer_refusal("1e300", 4, 100000), "is too large (at most 100000)");
    EXPECT_EQ(integer_refusal("-1e300", 4, 100000), "is too small (at least 4)");
    EXPECT_EQ(integer_refusal("99999999999999999999999", 1, 500), "is too large (at most 500)");
    EXPECT_EQ(integer_refusal("-99999999999999999999999", 1, 500), "is too small (at least 1)");
    EXPECT_EQ(integer_refusal("2.5", 1, 500), "is not an integer");
    EXPECT_EQ(integer_refusal("lots", 1, 500), "is not an integer");
    EXPECT_EQ(integer_refusal("0x10", 1, 500), "is not an integer");
}

TEST(IntegerRefusal, ValidateParametersUsesTheDeclaredMaximumAndCutsTheValue) {
    const std::vector<ParameterInfo> declared = {ParameterInfo::integer("np", 50, 4, 100000, "population")};
    const auto message = [&](const std::string& spec) {
        try {
            validate_parameters("demo", declared, Spec::parse(spec));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("demo:np=1e300"), "demo: parameter 'np' = 1e300 is too large (at most 100000)");
    EXPECT_EQ(message("demo:np=" + std::string(1000, '7')),
              "demo: parameter 'np' = '" + std::string(37, '7') +
                  "...' (1000 characters) is too large (at most "
                  "100000)");
    EXPECT_EQ(message("demo:" + std::string(60, 'k') + "=1"),
              "demo: unknown parameter '" + std::string(37, 'k') + "...' (60 characters); known: np");
}

const std::string header = "t,ud,uq,id,iq,omega,injected\n";
const std::string rows = "0,1,2,0,8,500,0\n0,1,2,0,8,501,0\n0,1,2,-2,8,500,1\n0,1,2,-2,8,501,1\n";

std::string read_error(const std::string& text) {
    std::istringstream in(text);
    try {
        pmsm::read_dataset_csv(in, "d.csv");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "accepted";
}

TEST(DatasetCsv, AByteOrderMarkIsAccepted) {
    std::istringstream in("\xEF\xBB\xBF" + header + rows);
    EXPECT_EQ(pmsm::read_dataset_csv(in, "d.csv").size(), 4u);
    std::istringstream with_metadata("\xEF\xBB\xBF# Rs=0.33\n" + header + rows);
    const pmsm::Dataset data = pmsm::read_dataset_csv(with_metadata, "d.csv");
    ASSERT_NE(data.find_metadata("Rs"), nullptr);
    EXPECT_EQ(*data.find_metadata("Rs"), "0.33");
}

TEST(DatasetCsv, ValuesBeyondOneBillionAreRefusedWithTheRange) {
    EXPECT_EQ(
        read_error(header + "0,1e300,2,0,8,500,0\n" + rows),
        "d.csv: line 2, column 'ud': 1e300 is outside [-1e9, 1e9] (the range of a dataset value; larger "
        "ones would overflow the fit)");
    EXPECT_EQ(read_error(header + "0,1,2,0,8,-1e400,0\n" + rows).substr(0, 51),
              "d.csv: line 2, column 'omega': -1e400 is outside [-");
    EXPECT_EQ(read_error(header + "0,1,2,0,8,1e9,0\n" + rows), "accepted"); // the limit itself is allowed
}

TEST(DatasetCsv, ALongCellIsCutInTheMessage) {
    EXPECT_EQ(read_error(header + "0," + std::string(1048576, '7') + "x,2,0,8,500,0\n" + rows),
              "d.csv: line 2, column 'ud': '" + std::string(37, '7') +
                  "...' (1048577 characters) is not a number");
    EXPECT_EQ(read_error("t,ud,uq,id,iq,omega," + std::string(100, 'z') + "\n"),
              "d.csv: line 1, column 7: unknown column '" + std::string(37, 'z') +
                  "...' (100 characters) (expected t,ud,uq,id,iq,omega[,injected])");
}

TEST(DatasetCsv, AMissingFileOrADirectorySaysSo) {
    try {
        pmsm::read_dataset_csv("/no/such/dir/d.csv");
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(),
                     "/no/such/dir/d.csv: cannot open the dataset file (No such file or directory)");
    }
    try {
        pmsm::read_dataset_csv("/tmp");
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "/tmp: is a directory, not a dataset file");
    }
}

TEST(LeastSquares, SingularDataAreRefusedNotReturnedAsInfinity) {
    // omega = 0 everywhere: the inductances and psi have no signal.
    std::istringstream in(header + "0,1,2,0,8,0,0\n0,1,2,0,8,0,0\n0,1,2,-2,8,0,1\n0,1,2,-2,8,0,1\n");
    const pmsm::Dataset data = pmsm::read_dataset_csv(in, "d.csv");
    const auto samples = pmsm::pair_samples(data, {0.25, 0.25, 0.25, 0.25});
    EXPECT_THROW(pmsm::solve_least_squares(samples), std::invalid_argument);
}

TEST(LeastSquares, ValuesAtTheLimitGiveFiniteResults) {
    // Every value at +-1e9 scale: the fit, its covariance and standard errors stay finite.
    std::istringstream in(header +
                          "0,1e9,-9e8,0,1e9,1e9,0\n0,9e8,-1e9,0,9e8,-1e9,0\n0,1e9,1e9,-1e9,1e9,9e8,1\n"
                          "0,-1e9,1e9,-9e8,-1e9,1e9,1\n0,5e8,1e9,0,-1e9,9e8,0\n0,1e9,-5e8,-1e9,1e9,-1e9,1\n");
    const pmsm::Dataset data = pmsm::read_dataset_csv(in, "d.csv");
    const auto samples = pmsm::pair_samples(data, {0.25, 0.25, 0.25, 0.25});
    const auto r = pmsm::solve_least_squares(samples);
    EXPECT_TRUE(r.theta.allFinite());
    EXPECT_TRUE(std::isfinite(r.f));
    EXPECT_TRUE(r.standard_error.allFinite());
    EXPECT_TRUE(std::isfinite(r.condition_number));
}

} // namespace
} // namespace mhb
