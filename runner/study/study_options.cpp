#include "runner/study/study_options.hpp"

#include <algorithm>
#include <boost/program_options/value_semantic.hpp>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <utility>

#include "problems/core/did_you_mean.hpp"
#include "problems/core/parameters.hpp"
#include "problems/core/spec_grid.hpp"
#include "problems/core/text_excerpt.hpp"
#include "results/protocols/protocol_registry.hpp"

namespace mhb {
namespace po = boost::program_options;

namespace {

// algorithms = / problems =: the first line of a source replaces the list it came with (a
// preset's, a file's); later ones add to it, each spec remembering where it was written.
void add_specs(Study& study, std::set<std::string>& seen, const std::string& key, const std::string& value,
               const std::string& where) {
    const bool algorithms = key[0] == 'a';
    auto& list = algorithms ? study.algorithms : study.problems;
    auto& origins = algorithms ? study.algorithm_origins : study.problem_origins;
    if (seen.insert(algorithms ? "algorithms" : "problems").second) {
        list.clear();
        origins.clear();
    }
    origins.resize(list.size());
    for (auto& spec : split_spec_list(value)) {
        list.push_back(std::move(spec));
        origins.push_back(where);
    }
}

// Every source adds to the list (a study file's plug-ins and the command line's), each as an
// absolute path so that study.ini finds it from anywhere; loading is the CLI's (the registries
// must know the plug-ins' names before the specs are checked).
void add_plugins(Study& study, const std::string& value) {
    for (const auto& path : split_spec_list(value)) {
        const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
        if (std::find(study.plugins.begin(), study.plugins.end(), absolute) == study.plugins.end())
            study.plugins.push_back(absolute);
    }
}

// budget = TEXT ...: each a whole budget; each line of a refusal its own error.
void add_budgets(std::vector<StudyBudget>& budgets, const std::string& value, const std::string& prefix,
                 std::vector<std::string>& errors) {
    for (const auto& text : split_spec_list(value)) {
        try {
            budgets.push_back(parse_budget(text));
        } catch (const std::invalid_argument& e) {
            std::string lines = e.what();
            for (std::size_t start = 0; start < lines.size();) {
                const auto end = std::min(lines.find('\n', start), lines.size());
                errors.push_back(prefix + lines.substr(start, end - start));
                start = end + 1;
            }
        }
    }
}

// seed = N: any 64-bit unsigned integer, written in full.
std::optional<std::uint64_t> parse_seed(const std::string& value) {
    std::uint64_t seed = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), seed);
    if (value.empty() || ec != std::errc() || ptr != value.data() + value.size())
        return std::nullopt;
    return seed;
}

} // namespace

po::options_description study_options() {
    po::options_description d("Study (the same names in study files: key = value)");
    const PrecisionRule rule; // its defaults, declared once
    using specs = std::vector<std::string>;
    // clang-format off
    d.add_options()
        ("algorithms", po::value<specs>()->multitoken()->composing(),
         "optimisers to compare, as name:key=value,...; several separated by spaces, or the option repeated. "
         "Braces make a grid: itlbo:tutorial={on,off},obl={on,off} is 4 variants, each labelled (itlbo[T+O-]); "
         "label=NAME names one (see `mhbench list algorithms`)")
        ("algorithm", po::value<specs>()->multitoken()->composing(), "same as --algorithms")
        ("problems", po::value<specs>()->multitoken()->composing(),
         "problems, as name:key=value,...; integer parameters may be ranges (bbob:f=1-24) and any "
         "parameter a grid (dim={2,5,10}) (see `mhbench list problems`)")
        ("problem", po::value<specs>()->multitoken()->composing(), "same as --problems")
        ("runs", po::value<std::string>(),
         "runs of each algorithm on each problem and budget (default 20), or auto: as many as the precision "
         "asks (see --precision)")
        ("precision", po::value<std::string>(),
         "with --runs auto: add runs to a cell (an algorithm on a problem at a budget) in rounds until the "
         "standard error of its mean difference to the reference, on log10(f - f*) (f where f* is unknown), "
         "is at most this, e.g. 0.05")
        ("max-runs", po::value<std::string>(),
         ("with --runs auto: the most runs a cell gets (default " + std::to_string(rule.max) + ")").c_str())
        ("initial-runs", po::value<std::string>(),
         ("with --runs auto: the runs every cell starts with (default " + std::to_string(rule.initial) + ")").c_str())
        ("round-runs", po::value<std::string>(),
         ("with --runs auto: the runs a round adds to an unsettled cell (default " + std::to_string(rule.step) + ")").c_str())
        ("seed", po::value<std::string>(), "study seed, 0 to 2^64-1; every run's seed is derived from it (default 1)")
        ("seeds", po::value<std::string>(),
         "common (default): run r on problem p starts from the same stream for every algorithm (common "
         "random numbers: runs pair across algorithms); per-algorithm: each algorithm spec gets its own streams")
        ("iterations", po::value<std::string>(),
         "budget: iterations per run after the initialisation (iteration 0). A study needs a budget "
         "(--iterations, --evaluations or --budget); a preset brings its own")
        ("evaluations", po::value<std::string>(),
         "budget: function evaluations per run (1e5 is accepted), or by the problem's dimension D: "
         "10000*dim (10000 x D) or dim10:200000+dim20:1000000 (a count per D listed; others are refused); "
         "with --iterations, whichever is spent first ends the run. Replaces a preset's budgets")
        ("budget", po::value<specs>()->multitoken()->composing(),
         "one budget as iterations=N,evaluations=N,target=E (any of them; evaluations as for --evaluations; "
         "relative_target=R instead of target stops at f - f* <= R x |f*|); "
         "repeat it to make the budget a factor of the study: --budget iterations=150 --budget "
         "evaluations=15050, each reported separately")
        ("budgets", po::value<specs>()->multitoken()->composing(), "same as --budget")
        ("target", po::value<std::string>(),
         "also stop a run once best f - f* <= this (problems with a known optimum); applies to every budget, "
         "replacing its target")
        ("relative-target", po::value<std::string>(),
         "also stop a run once best f - f* <= this x |f*| (problems with a known, non-zero optimum), e.g. 1e-6; "
         "applies to every budget, replacing its target; not with --target")
        ("protocol", po::value<std::string>(),
         "follow a CEC competition protocol: cec2017 or cec2022 (none: no protocol). The report adds the "
         "competition's tables per dimension and the organisers' result files (report/cec/); the problems "
         "must be of that suite and the budget give evaluations. The presets cec2017 and cec2022 set it")
        ("plugins", po::value<specs>()->multitoken()->composing(),
         "plug-in modules (shared libraries built with mhbench_add_plugin) whose optimisers and problems the "
         "study names; the option may be repeated. Their names must differ from every other; each module's "
         "SHA-256 joins the identity of its runs, so a rebuilt plug-in is noticed on resume")
        ("plugin", po::value<specs>()->multitoken()->composing(), "same as --plugins");
    // clang-format on
    return d;
}

void StudyOptionReader::apply(const std::string& key, const std::string& value, const std::string& where,
                              std::vector<std::string>& errors) {
    const std::string prefix = where.empty() ? "" : where + ": ";
    const auto fail = [&](const std::string& why) {
        errors.push_back(prefix + key + " = " + value_excerpt(value) + " " + why);
    };
    const bool is_list = key == "algorithms" || key == "algorithm" || key == "problems" || key == "problem" ||
                         key == "budget" || key == "budgets" || key == "plugins" || key == "plugin";
    if (!is_list && !seen_.insert(key).second) {
        errors.push_back(prefix + "'" + key + "' is given twice");
        return;
    }
    const auto read_integer = [&](long long max) -> std::optional<std::int64_t> {
        long long v = 0;
        if (!parse_integer(value, v)) {
            fail(integer_refusal(value, 1, max));
            return std::nullopt;
        }
        return v;
    };
    if (key == "algorithms" || key == "algorithm" || key == "problems" || key == "problem") {
        add_specs(study_, seen_, key, value, where);
    } else if (key == "plugins" || key == "plugin") {
        add_plugins(study_, value);
    } else if (key == "runs") {
        if (value == "auto") {
            study_.by_precision = study_.by_precision.value_or(PrecisionRule{});
        } else if (const auto v = read_integer(max_runs_per_pair)) {
            study_.runs = *v;
            study_.by_precision.reset();
        }
    } else if (key == "precision") {
        double v = 0;
        if (!parse_real(value, v) || !(v > 0)) {
            fail("is not a number in (0, inf)");
            precision_ = std::numeric_limits<double>::infinity(); // said once: not "needs precision" too
        } else {
            precision_ = v;
        }
    } else if (key == "max-runs" || key == "initial-runs" || key == "round-runs") {
        const auto v = read_integer(max_runs_per_pair);
        (key == "max-runs" ? max_runs_ : key == "initial-runs" ? initial_runs_ : round_runs_) = v;
    } else if (key == "seed") {
        if (const auto seed = parse_seed(value))
            study_.seed = *seed;
        else
            fail("is not an integer in [0, 2^64)");
    } else if (key == "seeds") {
        if (value == "common")
            study_.seeds = SeedMode::common;
        else if (value == "per-algorithm")
            study_.seeds = SeedMode::per_algorithm;
        else
            fail("is not one of {common, per-algorithm}");
    } else if (key == "iterations") {
        iterations_ = read_integer(1000000000000000LL);
    } else if (key == "evaluations") {
        if (DimensionEvaluations::written_in(value)) {
            try {
                evaluations_by_dimension_ = DimensionEvaluations::parse(value);
            } catch (const std::invalid_argument& e) {
                errors.push_back(prefix + e.what());
            }
        } else {
            evaluations_ = read_integer(1000000000000000LL);
        }
    } else if (key == "protocol") {
        if (value == "none")
            study_.protocol.clear();
        else if (find_protocol(value) != nullptr)
            study_.protocol = value;
        else
            fail("is not one of {" + protocol_names() + ", none}");
    } else if (key == "budget" || key == "budgets") {
        add_budgets(budgets_, value, prefix, errors);
    } else if (key == "target" || key == "relative-target") {
        double v = 0;
        if (!parse_real(value, v))
            fail("is not a finite number");
        else if (seen_.count(key == "target" ? "relative-target" : "target") != 0)
            errors.push_back(prefix +
                             "give target (f - f* <= E) or relative-target (f - f* <= R x |f*|), not both");
        else
            (key == "target" ? target_ : relative_target_) = v;
    } else {
        std::vector<std::string> known;
        for (const auto& option : study_options().options())
            known.push_back(option->long_name());
        const std::string hint = did_you_mean(closest_names(key, known));
        errors.push_back(prefix + "unknown option " + quoted_excerpt(key) +
                         (hint.empty() ? "" : "; " + hint));
    }
}

// The rule of runs by precision: this source's keys over what the study had (a preset's rule).
void StudyOptionReader::finish_precision(std::vector<std::string>& errors) {
    const bool given = precision_ || max_runs_ || initial_runs_ || round_runs_;
    if (!study_.by_precision) {
        if (given)
            errors.emplace_back("precision, max-runs, initial-runs and round-runs go with runs = auto");
        return;
    }
    PrecisionRule& rule = *study_.by_precision;
    rule.precision = precision_.value_or(rule.precision);
    rule.max = max_runs_.value_or(rule.max);
    rule.initial = initial_runs_.value_or(rule.initial);
    rule.step = round_runs_.value_or(rule.step);
    study_.runs = rule.max; // runs are numbered as if every cell had the most
}

void StudyOptionReader::finish(std::vector<std::string>& errors) {
    finish_precision(errors);
    std::vector<StudyBudget> budgets;
    if (iterations_ || evaluations_ || evaluations_by_dimension_) {
        StudyBudget b;
        b.max_iterations = iterations_;
        b.max_evaluations = evaluations_;
        b.evaluations_by_dimension = evaluations_by_dimension_;
        budgets.push_back(b);
    }
    budgets.insert(budgets.end(), budgets_.begin(), budgets_.end());
    const bool budget_given =
        seen_.count("iterations") != 0 || seen_.count("evaluations") != 0 || !budgets_.empty();
    if (budget_given)
        study_.budgets = budgets.empty() ? std::vector<StudyBudget>{StudyBudget{}} : budgets;
    // Either replaces every budget's target, of either kind: a budget has one target.
    if (target_ || relative_target_)
        for (auto& b : study_.budgets) {
            b.target_error = target_;
            b.relative_target = relative_target_;
        }
}

} // namespace mhb
