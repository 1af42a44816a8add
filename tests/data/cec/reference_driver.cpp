// Prints the official CEC code's f at points read from stdin, one value a line (%.17g), for
// tests/data/cec/make_reference.py. Our own code; it links the official function file, which is
// not in this repository:
//   g++ -O2 -DCEC_YEAR=17 -o ref17 reference_driver.cpp cec17_test_func.cpp   (CEC 2017)
//   g++ -O2 -DCEC_YEAR=22 -o ref22 reference_driver.cpp cec22_test_func.cpp   (CEC 2022)
// cec17_test_func.cpp's `#include <WINDOWS.H>` must be deleted first (it needs nothing from it).
// Run it where `input_data` is the suite's official data folder: ref17 F D < points.txt
#include <cstdio>
#include <cstdlib>
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

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s FUNCTION DIM < points\n", argv[0]);
        return 2;
    }
    const int function = std::atoi(argv[1]);
    const int dim = std::atoi(argv[2]);
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
}
