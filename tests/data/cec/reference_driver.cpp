// Prints the official CEC code's f at points read from stdin, one value a line (%.17g), for
// tests/data/cec/make_reference.py; or, with --time, the official code's nanoseconds per
// evaluation, for the side-by-side comparison in BENCHMARKS.md. Our own code; it links the
// official function file, which is not in this repository:
//   g++ -O2 -DCEC_YEAR=17 -o ref17 reference_driver.cpp cec17_test_func.cpp   (CEC 2017)
//   g++ -O2 -DCEC_YEAR=22 -o ref22 reference_driver.cpp cec22_test_func.cpp   (CEC 2022)
// Both official files' `#include <WINDOWS.H>` must be deleted first (they need nothing from it).
// Run it where `input_data` is the suite's official data folder:
//   ref17 F D < points.txt      f at each point (D numbers per point)
//   ref17 --time F D            "F D ns": one point per call, cycling through 64 points uniform in
//                               [-100, 100]^D (as functions_bench does), for at least 0.3 s
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

// The globals the official file declares `extern`.
double *OShift, *M, *y, *z, *x_bound;
int ini_flag = 0, n_flag, func_flag, *SS;

#if CEC_YEAR == 17
void cec17_test_func(double*, double*, int, int, int);
#define CEC_TEST_FUNC cec17_test_func
#else
void cec22_test_func(double*, double*, int, int, int);
#define CEC_TEST_FUNC cec22_test_func
#endif

namespace {

int print_values(int function, int dim) {
    std::vector<double> x;
    double v = 0;
    while (std::scanf("%lf", &v) == 1)
        x.push_back(v);
    for (std::size_t i = 0; i + static_cast<std::size_t>(dim) <= x.size();
         i += static_cast<std::size_t>(dim)) {
        double f = 0;
        CEC_TEST_FUNC(&x[i], &f, dim, 1, function);
        std::printf("%.17g\n", f);
    }
    return 0;
}

int print_time(int function, int dim) {
    constexpr std::size_t points = 64;
    const auto d = static_cast<std::size_t>(dim);
    std::mt19937_64 engine(2017);
    std::uniform_real_distribution<double> uniform(-100.0, 100.0);
    std::vector<double> x(points * d);
    for (double& v : x)
        v = uniform(engine);
    double f = 0;
    double sink = 0;
    CEC_TEST_FUNC(&x[0], &f, dim, 1, function); // the first call reads the data files: not timed
    long evaluations = 0;
    double seconds = 0;
    const auto start = std::chrono::steady_clock::now();
    while (seconds < 0.3) {
        for (int k = 0; k < 1024; ++k, ++evaluations) {
            CEC_TEST_FUNC(&x[(static_cast<std::size_t>(evaluations) % points) * d], &f, dim, 1, function);
            sink += f;
        }
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("%d %d %.1f\n", function, dim, seconds / static_cast<double>(evaluations) * 1e9 + 0.0 * sink);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const bool time = argc == 4 && std::strcmp(argv[1], "--time") == 0;
    if (argc != 3 && !time) {
        std::fprintf(stderr, "usage: %s FUNCTION DIM < points\n       %s --time FUNCTION DIM\n", argv[0],
                     argv[0]);
        return 2;
    }
    const int function = std::atoi(argv[time ? 2 : 1]);
    const int dim = std::atoi(argv[time ? 3 : 2]);
    return time ? print_time(function, dim) : print_values(function, dim);
}
