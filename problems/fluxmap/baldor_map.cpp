// The shipped Baldor flux map (data/baldor-ecs101m0h7ef4-400rpm.csv) and its best-known optima
// (data/baldor-optimum.csv), embedded in the executable
// by the assembler's .incbin as the CEC data are (problems/cec/cec_archives.cpp), so that the
// program needs no data directory at run time. The path comes from problems/CMakeLists.txt.
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/fluxmap/baldor_optimum.hpp"
#include "problems/fluxmap/flux_map.hpp"

#if !defined(MHB_FLUXMAP_BALDOR_CSV) || !defined(MHB_FLUXMAP_OPTIMUM_CSV)
#error "problems/CMakeLists.txt defines MHB_FLUXMAP_BALDOR_CSV and MHB_FLUXMAP_OPTIMUM_CSV"
#endif

asm(".pushsection .rodata.mhb_fluxmap_baldor,\"a\",@progbits\n"
    ".globl mhb_fluxmap_baldor_begin\n.hidden mhb_fluxmap_baldor_begin\n"
    "mhb_fluxmap_baldor_begin:\n"
    ".incbin \"" MHB_FLUXMAP_BALDOR_CSV "\"\n"
    ".globl mhb_fluxmap_baldor_end\n.hidden mhb_fluxmap_baldor_end\n"
    "mhb_fluxmap_baldor_end:\n"
    ".globl mhb_fluxmap_optimum_begin\n.hidden mhb_fluxmap_optimum_begin\n"
    "mhb_fluxmap_optimum_begin:\n"
    ".incbin \"" MHB_FLUXMAP_OPTIMUM_CSV "\"\n"
    ".globl mhb_fluxmap_optimum_end\n.hidden mhb_fluxmap_optimum_end\n"
    "mhb_fluxmap_optimum_end:\n"
    ".popsection\n");

extern "C" {
__attribute__((visibility("hidden"))) extern const char mhb_fluxmap_baldor_begin[];
__attribute__((visibility("hidden"))) extern const char mhb_fluxmap_baldor_end[];
__attribute__((visibility("hidden"))) extern const char mhb_fluxmap_optimum_begin[];
__attribute__((visibility("hidden"))) extern const char mhb_fluxmap_optimum_end[];
}

namespace mhb::fluxmap {

const FluxMap& baldor_flux_map() {
    static const FluxMap map = [] {
        std::istringstream in(std::string(mhb_fluxmap_baldor_begin, mhb_fluxmap_baldor_end));
        return read_flux_map_csv(in, baldor_map_name, 1);
    }();
    return map;
}

namespace {

// Rows `model,f,theta_1,...` after a header; read once.
std::vector<std::vector<std::string>> optimum_rows() {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(std::string(mhb_fluxmap_optimum_begin, mhb_fluxmap_optimum_end));
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
            fields.push_back(cell);
        rows.push_back(std::move(fields));
    }
    return rows;
}

double number(const std::string& text) {
    double v = 0;
    if (!parse_real(text, v))
        throw std::logic_error("fluxmap: data/baldor-optimum.csv holds '" + text + "', not a number");
    return v;
}

} // namespace

KnownOptimum baldor_optimum(Model model) {
    static const std::vector<std::vector<std::string>> rows = optimum_rows();
    const std::string name = model == Model::syrm ? "syrm" : "pmsyrm";
    const Eigen::Index n = parameter_count(model);
    for (const auto& row : rows)
        if (!row.empty() && row[0] == name && static_cast<Eigen::Index>(row.size()) == n + 2) {
            KnownOptimum best{number(row[1]), Eigen::VectorXd(n)};
            for (Eigen::Index j = 0; j < n; ++j)
                (*best.x)[j] = number(row[static_cast<std::size_t>(j + 2)]);
            return best;
        }
    throw std::logic_error("fluxmap: data/baldor-optimum.csv has no row for model " + name);
}

} // namespace mhb::fluxmap
