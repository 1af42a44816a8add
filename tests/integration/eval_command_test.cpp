// `mhbench eval` end to end: it prints, in another process, exactly the values the library
// computes (so instances are the same across processes), matches COCO's reference values, and
// names file, line and column for bad input.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>

#include "problems/core/parameters.hpp"
#include "problems/core/rng.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

struct EvalResult {
    int status = 0;
    std::string out; // stdout and stderr together
};

EvalResult run(const std::string& arguments) {
    const std::string command = std::string(MHB_CLI_PATH) + " " + arguments + " 2>&1";
    EvalResult r;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr)
        return {-1, "popen failed"};
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr)
        r.out += buffer.data();
    const int status = pclose(pipe);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::filesystem::path temp_file(const std::string& name, const std::string& content) {
    const auto path = std::filesystem::temp_directory_path() / ("mhb_eval_test_" + name);
    std::ofstream(path) << content;
    return path;
}

std::vector<double> parse_lines(const std::string& text) {
    std::vector<double> values;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        double v = 0;
        EXPECT_TRUE(parse_real(line, v)) << line;
        values.push_back(v);
    }
    return values;
}

TEST(EvalCommand, PrintsExactlyWhatTheLibraryComputesInAnotherProcess) {
    const std::string spec = "rastrigin:dim=5,shift=1,rotate=1,instance=3";
    const auto problem = builtin_problems().create(spec);
    Rng rng(17);
    std::string content = "# five points, spaces and commas\n\n";
    std::vector<double> expected;
    for (int k = 0; k < 5; ++k) {
        Eigen::VectorXd x(5);
        for (Eigen::Index i = 0; i < 5; ++i) {
            x[i] = rng.uniform(-5.12, 5.12);
            content += format_real(x[i]) + (i + 1 < 5 ? (k % 2 ? ", " : " ") : "\n");
        }
        expected.push_back(problem->evaluate(x));
    }
    const auto file = temp_file("points.txt", content);
    const EvalResult first = run("eval --problem " + spec + " --points " + file.string());
    const EvalResult second = run("eval --problem " + spec + " --points " + file.string());
    ASSERT_EQ(first.status, 0) << first.out;
    EXPECT_EQ(first.out, second.out);
    EXPECT_EQ(parse_lines(first.out), expected); // bit for bit: full precision round-trips
}

TEST(EvalCommand, MatchesCocoReferenceValues) {
    // Reference: tests/data/bbob_public_sample.csv (computed with COCO), f15 in dimension 10, instance 1.
    std::ifstream csv(std::string(MHB_TEST_DATA_DIR) + "/bbob_public_sample.csv");
    std::string line;
    std::string points;
    std::vector<double> expected;
    while (std::getline(csv, line)) {
        if (line.rfind("15,10,1,", 0) != 0)
            continue;
        std::vector<std::string> fields;
        std::istringstream row(line);
        std::string field;
        while (std::getline(row, field, ','))
            fields.push_back(field);
        points += fields[4] + "\n";
        expected.push_back(std::stod(fields[5]));
    }
    ASSERT_EQ(expected.size(), 3u);
    const auto file = temp_file("bbob.txt", points);
    const EvalResult r = run("eval --problem bbob:f=15,dim=10,instance=1 --points " + file.string());
    ASSERT_EQ(r.status, 0) << r.out;
    const auto got = parse_lines(r.out);
    ASSERT_EQ(got.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(got[i], expected[i], 1e-9 * std::fabs(expected[i]));
}

TEST(EvalCommand, MatchesTheOfficialCecCodeOnThePublicSample) {
    // tests/data/cec/cec_public_sample.csv (suite,function,dim,point_id,f,x), computed with the
    // official CEC 2017/2022 C code: every (suite, function, dim) in it, to 1e-10 relative.
    std::ifstream csv(std::string(MHB_TEST_DATA_DIR) + "/cec/cec_public_sample.csv");
    std::string line;
    std::getline(csv, line);                                                       // header
    std::map<std::string, std::pair<std::string, std::vector<double>>> by_problem; // spec -> points, f
    while (std::getline(csv, line)) {
        std::vector<std::string> fields;
        std::istringstream row(line);
        std::string field;
        while (std::getline(row, field, ','))
            fields.push_back(field);
        ASSERT_EQ(fields.size(), 6u) << line;
        auto& [points, expected] = by_problem[fields[0] + ":f=" + fields[1] + ",dim=" + fields[2]];
        points += fields[5] + "\n";
        expected.push_back(std::stod(fields[4]));
    }
    ASSERT_EQ(by_problem.size(), 4u);
    for (const auto& [spec, sample] : by_problem) {
        const auto file = temp_file("cec.txt", sample.first);
        const EvalResult r = run("eval --problem " + spec + " --points " + file.string());
        ASSERT_EQ(r.status, 0) << spec << ": " << r.out;
        const auto got = parse_lines(r.out);
        ASSERT_EQ(got.size(), sample.second.size()) << spec;
        for (std::size_t i = 0; i < got.size(); ++i)
            EXPECT_NEAR(got[i], sample.second[i], 1e-10 * std::fabs(sample.second[i]))
                << spec << " point " << i;
    }
}

TEST(EvalCommand, BadInputNamesFileLineAndColumn) {
    const auto wrong_count = temp_file("count.txt", "1 2\n1 2 3\n");
    EvalResult r = run("eval --problem sphere:dim=2 --points " + wrong_count.string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find(wrong_count.string() + ", line 2: 3 coordinates, but the problem has 2 dimensions"),
              std::string::npos)
        << r.out;
    const auto bad_number = temp_file("number.txt", "1,2\n0.5,abc\n");
    r = run("eval --problem sphere:dim=2 --points " + bad_number.string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find(", line 2, column 5 (coordinate 2): 'abc' is not a finite number"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("1\n"), std::string::npos) << "no partial output: " << r.out;
    r = run("eval --problem bbob:f=25,dim=2 --points " + bad_number.string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("bbob: parameter 'f' = 25 is outside [1, 24]"), std::string::npos) << r.out;
    r = run("eval --problem sphere:dim=2 --points /no/such/file");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("/no/such/file: cannot be opened"), std::string::npos) << r.out;
    r = run("eval --help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("--points"), std::string::npos);
}

} // namespace
} // namespace mhb
