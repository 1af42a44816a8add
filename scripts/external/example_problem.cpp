// The Rosenbrock function as an external problem written with the header-only C++ client
// (mhbench_external.hpp). Built as mhb_external_example_problem by tests/CMakeLists.txt; run by
// mhbench as `external:cmd=path/to/mhb_external_example_problem,params=dim=4`.
#include <string>

#include "mhbench_external.hpp"

int main() {
    return mhbench_external::serve_problem(
        "rosenbrock-cpp-1",
        [](const mhbench_external::Parameters& p) {
            const auto found = p.find("dim");
            const std::size_t dim = found == p.end() ? 2 : std::stoul(found->second);
            return mhbench_external::ProblemDescription{
                mhbench_external::Point(dim, -5.0), mhbench_external::Point(dim, 10.0), {}, 0.0};
        },
        [](const mhbench_external::Point& x) {
            double f = 0.0;
            for (std::size_t i = 0; i + 1 < x.size(); ++i)
                f +=
                    100.0 * (x[i + 1] - x[i] * x[i]) * (x[i + 1] - x[i] * x[i]) + (1.0 - x[i]) * (1.0 - x[i]);
            return f;
        });
}
