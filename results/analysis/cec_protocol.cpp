#include "results/analysis/cec_protocol.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "results/analysis/dimension_budget.hpp"
#include "results/analysis/evaluation_counts.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {
namespace {

// CEC 2017, section 2.2: the fractions of MaxFES after which the error is recorded.
constexpr std::array<double, 14> cec2017_fractions = {0.01, 0.02, 0.03, 0.05, 0.1, 0.2, 0.3,
                                                      0.4,  0.5,  0.6,  0.7,  0.8, 0.9, 1.0};
// CEC 2022, section 2.2: k = 0..15 in floor(D^(k/5 - 3) MaxFES).
constexpr int cec2022_checkpoints = 16;

const std::array<CecProtocol, 2>& protocols() {
    static const std::array<CecProtocol, 2> all = {
        CecProtocol{"cec2017", "CEC 2017", "cec2017", 51, "10000*dim", false, 2},
        CecProtocol{"cec2022", "CEC 2022", "cec2022", 30, "dim10:200000+dim20:1000000", true, 0},
    };
    return all;
}

std::string_view trim_line(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

} // namespace

std::vector<std::int64_t> CecProtocol::checkpoints(std::int64_t max_fes, std::int64_t dimension) const {
    std::vector<std::int64_t> out;
    if (!termination_row) {
        for (const double fraction : cec2017_fractions)
            out.push_back(std::max<std::int64_t>(1, evaluations_at(fraction, max_fes)));
        return out;
    }
    for (int k = 0; k < cec2022_checkpoints; ++k) {
        // In long double, and nudged up by a relative 1e-12, so that an exact product (20^-2 x 1e6 =
        // 2500) is not floored to one less by rounding in pow.
        const long double exact = std::pow(static_cast<long double>(dimension), k / 5.0L - 3.0L) *
                                  static_cast<long double>(max_fes);
        out.push_back(
            std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(exact * (1.0L + 1e-12L)))));
    }
    return out;
}

std::vector<std::string> CecProtocol::row_names() const {
    std::vector<std::string> out;
    if (!termination_row) {
        for (const double fraction : cec2017_fractions) {
            char text[32];
            std::snprintf(text, sizeof text, "%g x MaxFES", fraction);
            out.emplace_back(text);
        }
        return out;
    }
    for (int k = 0; k < cec2022_checkpoints; ++k)
        out.push_back("floor(D^(" + std::to_string(k) + "/5 - 3) x MaxFES)");
    out.emplace_back("FEterm (evaluations when the error first fell below 1e-8, else MaxFES)");
    return out;
}

std::span<const CecProtocol> cec_protocols() {
    return protocols();
}

const CecProtocol* find_cec_protocol(std::string_view name) {
    for (const auto& p : protocols())
        if (p.name == name)
            return &p;
    return nullptr;
}

std::string cec_protocol_names() {
    std::string out;
    for (const auto& p : protocols())
        out += (out.empty() ? "" : ", ") + std::string(p.name);
    return out;
}

std::optional<std::string> study_protocol(std::string_view study_text) {
    std::size_t start = 0;
    while (start < study_text.size()) {
        const auto end = std::min(study_text.find('\n', start), study_text.size());
        std::string_view line = trim_line(study_text.substr(start, end - start));
        start = end + 1;
        if (line.substr(0, 8) != "protocol")
            continue;
        line = trim_line(line.substr(8));
        if (!line.empty() && line.front() == '=')
            return std::string(trim_line(line.substr(1)));
    }
    return std::nullopt;
}

double cec_error(double f, double f_opt) {
    const double error = f - f_opt;
    return error < cec_error_threshold ? 0.0 : error;
}

double cec_error_at(const RunRecord& run, std::int64_t evaluations) {
    if (!run.f_opt)
        return NAN;
    return cec_error(value_at_evaluations(run, evaluations), *run.f_opt);
}

std::int64_t cec_termination_evaluations(const RunRecord& run, std::int64_t max_fes) {
    if (!run.f_opt)
        return max_fes;
    const double f_opt = *run.f_opt;
    return first_evaluation_reaching(run, [f_opt](double f) { return f - f_opt < cec_error_threshold; })
        .value_or(max_fes);
}

std::optional<CecFunction> cec_function(const std::string& problem, std::string_view family,
                                        std::int64_t dimension) {
    const SpecText spec = split_spec_text(problem);
    if (spec.name != family)
        return std::nullopt;
    CecFunction out;
    const auto f = spec_number(spec, "f");
    out.number = f ? static_cast<int>(*f) : 1; // the family's default function
    const auto dim = spec_number(spec, "dim");
    out.dimension = dim ? static_cast<std::int64_t>(*dim) : dimension;
    return out;
}

std::vector<CecProblem> cec_problems(const StudyIndex& index, const CecProtocol& protocol) {
    std::vector<CecProblem> out;
    for (const auto& problem : index.problems()) {
        const std::int64_t runs_dimension = problem_dimension(index, problem);
        const auto function = cec_function(problem, protocol.family, runs_dimension);
        if (!function)
            continue;
        CecProblem p;
        p.problem = problem;
        p.function = function->number;
        p.dimension = function->dimension;
        const auto from_budget = budget_evaluations_at(index.budget(), p.dimension);
        p.max_fes_from_budget = from_budget.has_value();
        p.max_fes = from_budget ? *from_budget : budget_evaluations(index, problem);
        out.push_back(std::move(p));
    }
    std::stable_sort(out.begin(), out.end(), [](const CecProblem& a, const CecProblem& b) {
        return a.dimension != b.dimension ? a.dimension < b.dimension : a.function < b.function;
    });
    return out;
}

} // namespace mhb
