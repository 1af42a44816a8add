// The `cec2017` and `cec2022` problem families: the CEC bound-constrained suites exact to the
// official C code, on [-100, 100]^D, f* = the suite's bias. `cec2017:f=1-30,dim=10` expands into
// the 30 problems of one dimension; a dimension without official data is refused when the problem
// is created (so a study reports it before any run starts).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "problems/cec/cec_function.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

class CecProblem final : public Problem {
public:
    CecProblem(cec::Suite suite, int number, int dimension)
        : suite_(suite), number_(number), function_(cec::shared_function(suite, number, dimension)),
          box_{Eigen::VectorXd::Constant(dimension, -100.0), Eigen::VectorXd::Constant(dimension, 100.0)},
          optimum_{cec::recipes(suite)[static_cast<std::size_t>(number) - 1].bias, function_->minimiser()} {}

    std::string name() const override { return std::string(cec::suite_name(suite_)); }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    std::optional<KnownOptimum> known_optimum() const override { return optimum_; }

    double evaluate(const Eigen::VectorXd& x) const override {
        if (x.size() != box_.dimension())
            throw std::invalid_argument(name() + ": f=" + std::to_string(number_) + " has " +
                                        std::to_string(box_.dimension()) + " dimensions, x has " +
                                        std::to_string(x.size()));
        return function_->value(x.data());
    }

    std::vector<std::string> warnings() const override {
        const std::string& note = cec::recipes(suite_)[static_cast<std::size_t>(number_) - 1].note;
        if (suite_ == cec::Suite::cec2017 && number_ == 2)
            return {"cec2017 f=2 (Sum of Different Power) was " + note};
        return {};
    }

private:
    cec::Suite suite_;
    int number_;
    std::shared_ptr<const cec::Function> function_;
    Box box_;
    KnownOptimum optimum_;
};

std::string cec_function_help(cec::Suite suite) {
    std::string s = "function number, as in the official code:";
    const auto& all = cec::recipes(suite);
    for (std::size_t f = 0; f < all.size(); ++f) {
        s.append(f == 0 ? " " : "; ").append(std::to_string(f + 1)).append(" ").append(all[f].name);
        if (!all[f].note.empty())
            s.append(" (").append(all[f].note).append(")");
    }
    return s + "; a range such as 1-" + std::to_string(all.size()) + " expands";
}

// "1-10,21-28" for the sorted numbers 1...10, 21...28.
std::string number_ranges(const std::vector<int>& numbers) {
    std::string out;
    for (std::size_t i = 0; i < numbers.size();) {
        std::size_t j = i;
        while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1)
            ++j;
        if (!out.empty())
            out.append(",");
        out.append(std::to_string(numbers[i]));
        if (j > i)
            out.append(j == i + 1 ? "," : "-").append(std::to_string(numbers[j]));
        i = j + 1;
    }
    return out;
}

std::string dimension_help(cec::Suite suite) {
    // The function numbers grouped by the dimensions their data exist for, in order of first use.
    std::vector<std::pair<std::vector<int>, std::vector<int>>> groups;
    const auto& all = cec::recipes(suite);
    for (std::size_t f = 0; f < all.size(); ++f) {
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&](const auto& g) { return g.first == all[f].dimensions; });
        if (it == groups.end()) {
            groups.emplace_back(all[f].dimensions, std::vector<int>{});
            it = groups.end() - 1;
        }
        it->second.push_back(static_cast<int>(f) + 1);
    }
    std::string s = "dimension, where the official data exist:";
    for (std::size_t g = 0; g < groups.size(); ++g)
        s.append(g == 0 ? " f=" : "; f=")
            .append(number_ranges(groups[g].second))
            .append(" in ")
            .append(cec::dimension_list(groups[g].first));
    return s;
}

ProblemRegistry::Factory factory(cec::Suite suite) {
    return [suite](const ParameterValues& p) -> std::unique_ptr<Problem> {
        const auto number = static_cast<int>(p.integer("f"));
        const auto dimension = static_cast<int>(p.integer("dim"));
        cec::check_available(suite, number, dimension);
        return std::make_unique<CecProblem>(suite, number, dimension);
    };
}

} // namespace

void register_cec(ProblemRegistry& registry) {
    using cec::Suite;
    registry.add(
        {"cec2017",
         1,
         "the CEC 2017 bound-constrained suite, 30 functions exact to the official code (f=2 is "
         "excluded from the competition), on [-100, 100]^dim; f* = 100 f and x* known",
         "Awad, Ali, Liang, Qu, Suganthan (2016), Problem definitions and evaluation criteria for the "
         "CEC 2017 special session on single objective bound constrained real-parameter numerical "
         "optimization, NTU technical report; code and data: P-N-Suganthan/CEC2017-BoundContrained "
         "(commit 2c54cad)",
         {ParameterInfo::integer("f", 1, 1, 30, cec_function_help(Suite::cec2017)).ranged(),
          ParameterInfo::integer("dim", 10, 2, cec::max_dimension, dimension_help(Suite::cec2017))},
         factory(Suite::cec2017)});
    registry.add(
        {"cec2022",
         1,
         "the CEC 2022 bound-constrained suite, 12 functions exact to the official code, on "
         "[-100, 100]^dim; f* = the function's bias and x* known",
         "Kumar, Price, Mohamed, Hadi, Suganthan (2021), Problem definitions and evaluation criteria "
         "for the CEC 2022 special session on single objective bound constrained numerical "
         "optimization, NTU technical report; code and data: P-N-Suganthan/2022-SO-BO (commit de20505)",
         {ParameterInfo::integer("f", 1, 1, 12, cec_function_help(Suite::cec2022)).ranged(),
          ParameterInfo::integer("dim", 10, 2, 20, dimension_help(Suite::cec2022))},
         factory(Suite::cec2022)});
}

} // namespace mhb
