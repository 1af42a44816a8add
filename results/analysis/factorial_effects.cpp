#include "results/analysis/factorial_effects.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp" // CSV as the store writes it, for every room
#include "results/table_model/table.hpp"

namespace mhb {

namespace {

// Beyond this many factors a design has more variants than any study runs; refusing keeps 1 << k safe.
constexpr std::size_t max_factors = 16;

bool bit(std::size_t m, std::size_t j) {
    return ((m >> j) & 1U) != 0;
}

std::string combination_text(const std::vector<std::string>& factors, std::size_t m) {
    std::string out;
    for (std::size_t j = 0; j < factors.size(); ++j)
        out += (j == 0 ? "" : ",") + factors[j] + (bit(m, j) ? "=on" : "=off");
    return out;
}

// One (problem, run index) with every variant's final f and known optimum (NaN where unknown).
struct RawBlock {
    std::vector<double> f;
    std::vector<double> f_opt;
};

struct ProblemBlocks {
    std::string problem;
    std::vector<RawBlock> blocks;
    std::size_t left_out = 0;
    std::size_t infinite = 0; // runs of the kept blocks whose f is +inf (or -inf)
    bool has_optimum = true;
    bool paired = false;
    // log10(f - f*) needs f* and finite f: log10(inf) = inf would make every effect inf or NaN.
    [[nodiscard]] bool log_scale() const { return has_optimum && infinite == 0; }
};

ProblemBlocks collect_blocks(const StudyIndex& index, const FactorialDesign& design,
                             const std::string& problem) {
    ProblemBlocks out;
    out.problem = problem;
    out.paired = index.paired(problem);
    std::vector<const RunGroup*> groups;
    std::set<std::int64_t> run_indices;
    for (const auto& a : design.algorithms) {
        const RunGroup* g = index.find(problem, a);
        groups.push_back(g);
        if (g != nullptr)
            for (const auto* r : g->runs)
                run_indices.insert(r->run_index);
    }
    for (const std::int64_t i : run_indices) {
        RawBlock block;
        bool complete = true;
        for (const RunGroup* g : groups) {
            const RunRecord* r = g == nullptr ? nullptr : g->run_with_index(i);
            if (r == nullptr) { // the variant failed (or never ran) at this run index
                complete = false;
                break;
            }
            block.f.push_back(r->best_f);
            block.f_opt.push_back(r->f_opt ? *r->f_opt : std::numeric_limits<double>::quiet_NaN());
            out.has_optimum = out.has_optimum && r->f_opt.has_value() && std::isfinite(*r->f_opt);
        }
        if (complete) {
            out.infinite += static_cast<std::size_t>(
                std::count_if(block.f.begin(), block.f.end(), [](double f) { return std::isinf(f); }));
            out.blocks.push_back(std::move(block));
        } else {
            ++out.left_out;
        }
    }
    return out;
}

std::vector<double> responses(const RawBlock& block, ResponseScale scale) {
    if (scale == ResponseScale::rank)
        return average_ranks(block.f);
    std::vector<double> out;
    for (std::size_t m = 0; m < block.f.size(); ++m)
        out.push_back(gap_response(block.f[m], block.f_opt[m]));
    return out;
}

EffectDirection direction(const EffectEstimate& e, double alpha) {
    if (!(e.adjusted_p < alpha) || e.mean == 0.0)
        return EffectDirection::none;
    // The signed-rank statistic's side of its null mean (n (n + 1) / 4 over the non-zero effects).
    double nonzero = 0.0;
    for (double v : e.per_block)
        nonzero += v != 0.0 ? 1.0 : 0.0;
    const double centred = e.test.statistic - nonzero * (nonzero + 1.0) / 4.0;
    if ((centred < 0.0) != (e.mean < 0.0))
        return EffectDirection::disagree;
    return e.mean < 0 ? EffectDirection::lowers : EffectDirection::raises;
}

std::string reading(const EffectEstimate& e, const std::vector<std::string>& factors, ResponseScale scale) {
    if (e.direction == EffectDirection::none)
        return "no significant effect";
    if (e.direction == EffectDirection::disagree)
        return "significant, but the mean and the signed ranks disagree in direction: inspect the blocks";
    const std::string amount = format_number(std::fabs(e.mean), 3);
    const std::string response =
        scale == ResponseScale::log10_gap ? "log10(f - f*)" : "the within-block rank";
    if (e.factors.size() == 1)
        return factors[e.factors[0]] + (e.mean < 0 ? " on lowers " : " on raises ") + response + " by " +
               amount + (e.mean < 0 ? ": helps" : ": hurts");
    const std::string& a = factors[e.factors[0]];
    const std::string& b = factors[e.factors[1]];
    return "interaction " + format_number(e.mean, 3) + ": " + a +
           (e.mean < 0 ? " helps more (or hurts less) with " : " helps less (or hurts more) with ") + b +
           " on, and vice versa";
}

} // namespace

std::string FactorialDesign::description() const {
    return name + ": " + join(factors, " x ") + " (2^" + std::to_string(factors.size()) + ")";
}

namespace {

// The parameters that vary among the variants, each an on/off switch in every full spec; `why_not`
// says why not when one is missing from a spec or varies otherwise.
std::vector<std::string> varying_switches(const std::vector<SpecText>& specs, std::string& why_not) {
    std::set<std::string> keys;
    for (const auto& s : specs)
        for (const auto& [key, value] : s.parameters)
            keys.insert(key);
    std::vector<std::string> factors;
    for (const auto& key : keys) {
        std::set<std::string> values;
        for (const auto& s : specs) {
            const auto it = s.parameters.find(key);
            if (it == s.parameters.end()) {
                why_not = "parameter '" + key + "' is missing from the full spec of some variant";
                return {};
            }
            values.insert(it->second);
        }
        if (values.size() == 1)
            continue;
        for (const auto& v : values)
            if (v != "on" && v != "off") {
                why_not = "parameter '" + key + "' varies (" + join({values.begin(), values.end()}, ", ") +
                          ") and is not an on/off switch";
                return {};
            }
        factors.push_back(key);
    }
    return factors;
}

// The variant of each combination of the switches (bit j: factor j on); `why_not` says why not when
// a combination appears twice or is missing.
std::vector<std::string> variants_by_combination(const std::vector<std::string>& algorithms,
                                                 const std::vector<SpecText>& specs,
                                                 const std::vector<std::string>& factors,
                                                 std::string& why_not) {
    const std::size_t variants = std::size_t{1} << factors.size();
    std::vector<std::string> by_combination(variants);
    for (std::size_t i = 0; i < specs.size(); ++i) {
        std::size_t m = 0;
        for (std::size_t j = 0; j < factors.size(); ++j)
            if (specs[i].parameters.at(factors[j]) == "on")
                m |= std::size_t{1} << j;
        if (!by_combination[m].empty()) {
            why_not = "combination " + combination_text(factors, m) + " appears twice (" + by_combination[m] +
                      ", " + algorithms[i] + ")";
            return {};
        }
        by_combination[m] = algorithms[i];
    }
    std::vector<std::string> missing;
    for (std::size_t m = 0; m < variants; ++m)
        if (by_combination[m].empty())
            missing.push_back(combination_text(factors, m));
    if (!missing.empty()) {
        why_not = std::to_string(algorithms.size()) + " variants for " + std::to_string(factors.size()) +
                  " on/off switches (" + join(factors, ", ") + ") need " + std::to_string(variants) +
                  "; missing: " + join(missing, "; ");
        return {};
    }
    return by_combination;
}

} // namespace

DesignCandidate detect_factorial_design(const std::vector<std::string>& algorithms,
                                        const std::vector<std::string>& full_specs) {
    if (algorithms.size() != full_specs.size())
        throw std::logic_error("detect_factorial_design: one full spec per algorithm");
    DesignCandidate c;
    if (algorithms.empty()) {
        c.why_not = "no variants";
        return c;
    }
    std::vector<SpecText> specs;
    for (const auto& f : full_specs)
        specs.push_back(split_spec_text(f));
    c.name = specs.front().name;
    for (const auto& s : specs)
        if (s.name != c.name) {
            c.why_not = "variants of different algorithms (" + c.name + ", " + s.name + ")";
            return c;
        }
    if (algorithms.size() < 2) {
        c.why_not = "a single variant";
        return c;
    }
    const std::vector<std::string> factors = varying_switches(specs, c.why_not);
    if (!c.why_not.empty())
        return c;
    if (factors.empty()) {
        c.why_not = "the variants do not differ in any parameter";
        return c;
    }
    if (factors.size() > max_factors) {
        c.why_not = std::to_string(factors.size()) + " varying switches: too many for a full factorial";
        return c;
    }
    std::vector<std::string> by_combination = variants_by_combination(algorithms, specs, factors, c.why_not);
    if (!c.why_not.empty())
        return c;
    c.design = FactorialDesign{c.name, factors, std::move(by_combination)};
    return c;
}

std::vector<DesignCandidate> find_factorial_designs(const StudyIndex& index) {
    std::vector<std::string> names;
    std::map<std::string, std::vector<std::string>> members;
    for (const auto& a : index.algorithms()) {
        const std::string name = split_spec_text(index.full_spec(a)).name;
        if (!members.count(name))
            names.push_back(name);
        members[name].push_back(a);
    }
    std::vector<DesignCandidate> out;
    for (const auto& name : names) {
        const auto& algorithms = members[name];
        if (algorithms.size() < 2)
            continue;
        std::vector<std::string> full;
        for (const auto& a : algorithms)
            full.push_back(index.full_spec(a));
        out.push_back(detect_factorial_design(algorithms, full));
    }
    return out;
}

std::string scale_name(ResponseScale scale) {
    return scale == ResponseScale::log10_gap ? "log10(f - f*)" : "within-block rank";
}

double gap_floor(double f_opt) {
    return std::max(1e-300, 4.0 * std::numeric_limits<double>::epsilon() * std::fabs(f_opt));
}

double gap_response(double f, double f_opt) {
    return std::log10(std::max(f - f_opt, gap_floor(f_opt)));
}

EffectAnalysis analyse_factorial_blocks(const std::vector<std::vector<double>>& blocks,
                                        const std::vector<std::string>& factors, ResponseScale scale,
                                        double alpha) {
    const std::size_t k = factors.size();
    if (k == 0 || k > max_factors)
        throw std::invalid_argument("factorial analysis: 1 to 16 factors, not " + std::to_string(k));
    const std::size_t variants = std::size_t{1} << k;
    for (const auto& b : blocks)
        if (b.size() != variants)
            throw std::invalid_argument("factorial analysis: a block has " + std::to_string(b.size()) +
                                        " responses for " + std::to_string(variants) + " variants");
    EffectAnalysis out;
    out.scale = scale;
    out.blocks = blocks.size();
    // Contrasts: main effects, then interactions in (i, j) order with i < j.
    std::vector<std::vector<std::size_t>> contrasts;
    for (std::size_t j = 0; j < k; ++j)
        contrasts.push_back({j});
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = i + 1; j < k; ++j)
            contrasts.push_back({i, j});
    const double half = static_cast<double>(variants) / 2.0; // variants = 2^k is even
    for (const auto& contrast : contrasts) {
        EffectEstimate e;
        e.factors = contrast;
        e.name =
            contrast.size() == 1 ? factors[contrast[0]] : factors[contrast[0]] + " x " + factors[contrast[1]];
        for (const auto& b : blocks) {
            double plus = 0.0;
            double minus = 0.0;
            for (std::size_t m = 0; m < variants; ++m) {
                const bool positive =
                    contrast.size() == 1 ? bit(m, contrast[0]) : bit(m, contrast[0]) == bit(m, contrast[1]);
                (positive ? plus : minus) += b[m];
            }
            e.per_block.push_back(plus / half - minus / half);
        }
        e.mean = e.per_block.empty() ? 0.0 : mean(e.per_block);
        e.median = median_of(e.per_block);
        e.test = signed_rank_test(e.per_block, std::vector<double>(e.per_block.size(), 0.0));
        out.effects.push_back(std::move(e));
    }
    std::vector<double> raw;
    for (const auto& e : out.effects)
        raw.push_back(e.test.p_value);
    const auto adjusted = holm_adjust(raw);
    for (std::size_t i = 0; i < out.effects.size(); ++i) {
        out.effects[i].adjusted_p = adjusted[i];
        out.effects[i].direction = direction(out.effects[i], alpha);
        out.effects[i].reading = reading(out.effects[i], factors, scale);
    }
    // Level means: per block the mean over the variants at the level(s), then the mean over blocks.
    const auto level_mean = [&](const auto& selects) {
        double total = 0.0;
        for (const auto& b : blocks) {
            double sum = 0.0;
            double count = 0.0;
            for (std::size_t m = 0; m < variants; ++m)
                if (selects(m)) {
                    sum += b[m];
                    count += 1.0;
                }
            total += sum / count;
        }
        return blocks.empty() ? std::numeric_limits<double>::quiet_NaN()
                              : total / static_cast<double>(blocks.size());
    };
    for (std::size_t j = 0; j < k; ++j)
        for (const bool level : {false, true})
            out.level_means.push_back({j, level, std::nullopt, false,
                                       level_mean([&](std::size_t m) { return bit(m, j) == level; })});
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = i + 1; j < k; ++j)
            for (const bool li : {false, true})
                for (const bool lj : {false, true})
                    out.level_means.push_back({i, li, j, lj, level_mean([&](std::size_t m) {
                                                   return bit(m, i) == li && bit(m, j) == lj;
                                               })});
    return out;
}

std::vector<EffectAnalysis> factorial_effects(const StudyIndex& index, const FactorialDesign& design,
                                              double alpha) {
    std::vector<ProblemBlocks> problems;
    for (const auto& p : index.problems()) {
        ProblemBlocks blocks = collect_blocks(index, design, p);
        if (!blocks.blocks.empty())
            problems.push_back(std::move(blocks));
    }
    std::vector<EffectAnalysis> out;
    const auto analyse = [&](const std::vector<const ProblemBlocks*>& parts, ResponseScale scale,
                             std::string name) {
        std::vector<std::vector<double>> responses_by_block;
        for (const auto* part : parts)
            for (const auto& b : part->blocks)
                responses_by_block.push_back(responses(b, scale));
        EffectAnalysis a = analyse_factorial_blocks(responses_by_block, design.factors, scale, alpha);
        a.problem = std::move(name);
        a.problems = parts.size();
        a.paired = std::all_of(parts.begin(), parts.end(), [](const ProblemBlocks* p) { return p->paired; });
        for (const auto* part : parts) {
            a.left_out += part->left_out;
            a.infinite_runs += part->infinite;
        }
        out.push_back(std::move(a));
    };
    bool all_log_scale = true;
    std::vector<const ProblemBlocks*> all;
    for (const auto& p : problems) {
        analyse({&p}, p.log_scale() ? ResponseScale::log10_gap : ResponseScale::rank, p.problem);
        all_log_scale = all_log_scale && p.log_scale();
        all.push_back(&p);
    }
    if (all.size() >= 2)
        analyse(all, all_log_scale ? ResponseScale::log10_gap : ResponseScale::rank,
                "all problems (" + std::to_string(all.size()) + ")");
    return out;
}

std::string effect_means_csv(const std::vector<DesignEffects>& designs) {
    std::string out = "design,problem,scale,blocks,factor,level,factor2,level2,mean_response\n";
    const auto level_text = [](bool on) { return on ? "on" : "off"; };
    for (const auto& d : designs)
        for (const auto& a : d.analyses)
            for (const auto& l : a.level_means)
                out += csv_field(d.design.description()) + ',' + csv_field(a.problem) + ',' +
                       csv_field(scale_name(a.scale)) + ',' + std::to_string(a.blocks) + ',' +
                       csv_field(d.design.factors[l.factor]) + ',' + level_text(l.level) + ',' +
                       (l.second_factor ? csv_field(d.design.factors[*l.second_factor]) : "") + ',' +
                       (l.second_factor ? level_text(l.second_level) : "") + ',' + csv_number(l.mean) + '\n';
    return out;
}

} // namespace mhb
