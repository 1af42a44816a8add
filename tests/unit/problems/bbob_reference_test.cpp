// The BBOB suite against reference values computed with COCO's own code
// (tests/data/bbob_public_sample.csv, copied from shared/testdata: columns function, dimension,
// instance, point id, x (space-separated), f, f_opt; 3 points for each of the 24 functions in
// dimensions 2 and 10, instance 1). Every function must match to 1e-9 relative (1e-9 absolute
// near zero) and report COCO's f_opt exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "problems/problem_registry.hpp"
#include "results/csv.hpp"

namespace mhb {
namespace {

TEST(BbobReference, EveryFunctionMatchesCocoValues) {
    const CsvTable table = read_csv(std::string(MHB_TEST_DATA_DIR) + "/bbob_public_sample.csv");
    const std::size_t c_function = table.column("function");
    const std::size_t c_dimension = table.column("dimension");
    const std::size_t c_instance = table.column("instance");
    const std::size_t c_x = table.column("x");
    const std::size_t c_f = table.column("f");
    const std::size_t c_fopt = table.column("f_opt");
    std::set<std::int64_t> functions_seen;
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
        const std::int64_t f = table.integer(row, c_function);
        const std::int64_t dim = table.integer(row, c_dimension);
        const std::int64_t instance = table.integer(row, c_instance);
        const std::string spec =
            "bbob:f=" + std::to_string(f) + ",dim=" + std::to_string(dim) + ",instance=" + std::to_string(instance);
        const auto problem = builtin_problems().create(spec);
        std::istringstream coordinates(table.rows[row][c_x]);
        Eigen::VectorXd x(dim);
        for (Eigen::Index i = 0; i < dim; ++i)
            ASSERT_TRUE(coordinates >> x[i]) << spec << " row " << table.line_numbers[row];
        const double expected = table.number(row, c_f);
        const double got = problem->evaluate(x);
        const double tolerance = 1e-9 * std::max(1.0, std::fabs(expected));
        EXPECT_NEAR(got, expected, tolerance) << spec << " point " << table.rows[row][table.column("point_id")];
        ASSERT_TRUE(problem->known_optimum().has_value());
        EXPECT_EQ(problem->known_optimum()->f, table.number(row, c_fopt)) << spec;
        functions_seen.insert(f);
    }
    EXPECT_EQ(functions_seen.size(), 24u);
}

} // namespace
} // namespace mhb
