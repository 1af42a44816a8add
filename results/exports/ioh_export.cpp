#include "results/exports/ioh_export.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <system_error>

#include "problems/core/fnv1a.hpp"
#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace mhb {

namespace fs = std::filesystem;

namespace {

// IOH's BBOB problem names (ioh/problem/bbob/*.hpp), by function number.
const char* const bbob_names[24] = {
    "Sphere",           "Ellipsoid",     "Rastrigin",     "BuecheRastrigin",    "LinearSlope",
    "AttractiveSector", "StepEllipsoid", "Rosenbrock",    "RosenbrockRotated",  "EllipsoidRotated",
    "Discus",           "BentCigar",     "SharpRidge",    "DifferentPowers",    "RastriginRotated",
    "Weierstrass",      "Schaffers10",   "Schaffers1000", "GriewankRosenbrock", "Schwefel",
    "Gallagher101",     "Gallagher21",   "Katsuura",      "LunacekBiRastrigin"};

// The classic functions in a fixed order: function_id 101 + position. New functions go at the end.
const char* const classic_names[] = {
    "sphere",        "ellipsoid",  "schwefel_1_2", "schwefel_2_21", "schwefel_2_22", "step",
    "quartic",       "rosenbrock", "zakharov",     "rastrigin",     "ackley",        "griewank",
    "schwefel_2_26", "levy",       "weierstrass",  "penalized_1",   "penalized_2"};

constexpr int pmsm_id = 200;
constexpr int variant_scale = 1000000; // base * variant_scale + 1 + hash % (variant_scale - 1)

// Names go into file names: no path separators, spaces or other punctuation.
std::string file_name_part(const std::string& text) {
    std::string out;
    for (const char c : text)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
    return out;
}

// A non-negative integer parameter, if the text is one.
std::optional<std::int64_t> integer_parameter(const SpecText& spec, const std::string& key) {
    const auto it = spec.parameters.find(key);
    if (it == spec.parameters.end())
        return std::nullopt;
    std::int64_t value = 0;
    const std::string& text = it->second;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || value < 0 || value > 2147483647)
        return std::nullopt;
    return value;
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (static_cast<unsigned char>(c) < 0x20)
            continue; // control characters never occur in specs; drop rather than escape
        out += c;
    }
    return out + "\"";
}

// A JSON number as IOH formats it; JSON has no nan/inf: those become null.
std::string json_number(double value) {
    return std::isfinite(value) ? ioh_shortest(value) : "null";
}

// raw_y as the .dat holds it: "None" (IOH's no-value mark) when not finite.
std::string dat_value(double value, IohPrecision precision, std::size_t& none_values) {
    if (std::isfinite(value))
        return precision == IohPrecision::logger ? ioh_fixed(value) : ioh_shortest(value);
    ++none_values;
    return "None";
}

struct Row {
    std::int64_t evaluations = 0;
    double y = 0.0; // raw_y
};

struct ExportedRun {
    const RunRecord* record = nullptr;
    std::int64_t instance = 1;
    std::vector<Row> rows;
    std::int64_t best_evaluations = 0; // of the last improvement
    double best_y = 0.0;
};

// The rows IOH's analyzer logger writes for a run, from its exact improvement trace.
ExportedRun exact_rows(const RunRecord& r, double shift) {
    ExportedRun run;
    run.record = &r;
    for (const auto& p : r.improvements->points)
        run.rows.push_back({p.evaluations, p.best_f - shift});
    if (!run.rows.empty()) {
        run.best_evaluations = run.rows.back().evaluations;
        run.best_y = run.rows.back().y;
        // The last evaluation, when it was not an improvement, with its own f.
        if (r.evaluations > run.rows.back().evaluations)
            run.rows.push_back({r.evaluations, r.improvements->last_f - shift});
    }
    return run;
}

// For runs stored without improvements: the strict improvements among what was recorded (ends of
// iterations, grid checkpoints, the final best), each at the evaluation where it was recorded.
ExportedRun grid_rows(const RunRecord& r, double shift) {
    std::vector<std::pair<std::int64_t, double>> points;
    for (const auto& p : r.curve)
        points.emplace_back(p.evaluations, p.best_f);
    for (const auto& c : r.checkpoints)
        points.emplace_back(c.evaluations, c.best_f);
    points.emplace_back(r.evaluations, r.best_f);
    std::stable_sort(points.begin(), points.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    ExportedRun run;
    run.record = &r;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [evaluations, f] : points) {
        if (evaluations <= 0 || !(f < best))
            continue;
        best = f;
        run.rows.push_back({evaluations, f - shift});
    }
    if (!run.rows.empty()) {
        run.best_evaluations = run.rows.back().evaluations;
        run.best_y = run.rows.back().y;
    }
    return run;
}

struct Scenario {
    std::size_t dimension = 0;
    std::vector<ExportedRun> runs;
};

struct FunctionExport {
    IohFunction function;
    std::vector<Scenario> scenarios; // by first appearance
    std::size_t approximate_runs = 0;
};

// Removes what an earlier export wrote under `dir`: IOH files in its algorithm folders, and the
// folders themselves when that empties them.
void remove_earlier_export(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        return;
    for (const auto& folder : fs::directory_iterator(dir, ec)) {
        if (!folder.is_directory(ec))
            continue;
        std::vector<fs::path> stale;
        for (const auto& entry : fs::directory_iterator(folder.path(), ec)) {
            const std::string name = entry.path().filename().string();
            if ((entry.is_directory(ec) && name.rfind("data_f", 0) == 0) ||
                (name.rfind("IOHprofiler_f", 0) == 0 && entry.path().extension() == ".json"))
                stale.push_back(entry.path());
        }
        for (const auto& path : stale)
            fs::remove_all(path, ec);
        if (fs::is_empty(folder.path(), ec))
            fs::remove(folder.path(), ec);
    }
}

} // namespace

IohFunction ioh_function(const std::string& problem_spec) {
    const SpecText spec = split_spec_text(problem_spec);
    IohFunction out;
    out.suite = "mhbench";
    std::set<std::string> consumed = {"dim", "instance"};
    int base = 0;
    if (spec.name == "bbob") {
        const std::int64_t f = integer_parameter(spec, "f").value_or(spec.parameters.count("f") ? 0 : 1);
        if (f >= 1 && f <= 24) {
            out.suite = "BBOB";
            base = static_cast<int>(f);
            out.name = bbob_names[f - 1];
            out.minus_f_opt = true;
            consumed.insert("f");
        }
    } else if (spec.name == "pmsm") {
        base = pmsm_id;
    } else {
        const auto* found = std::find(std::begin(classic_names), std::end(classic_names), spec.name);
        if (found != std::end(classic_names))
            base = 101 + static_cast<int>(found - std::begin(classic_names));
    }
    if (base == 0) // a family the table does not know (or bbob with an f it does not have)
        base = 300 + static_cast<int>(fnv1a_64(spec.name) % 700);
    if (out.name.empty())
        out.name = file_name_part(spec.name);

    if (const auto instance = integer_parameter(spec, "instance"))
        out.instance = *instance;
    else if (spec.parameters.count("instance") != 0)
        consumed.erase("instance"); // not a number: it distinguishes functions instead
    if (const auto dim = integer_parameter(spec, "dim"))
        out.dimension = *dim;

    std::string others;
    std::string suffix;
    for (const auto& [key, value] : spec.parameters) {
        if (consumed.count(key) != 0)
            continue;
        others += (others.empty() ? "" : ",") + key + "=" + value;
        suffix += "_" + file_name_part(key) + "_" + file_name_part(value);
    }
    out.id = base;
    if (!others.empty()) {
        out.id = base * variant_scale + 1 + static_cast<int>(fnv1a_64(others) % (variant_scale - 1));
        // File names stay short: a long list of parameters is cut and keeps its hash.
        constexpr std::size_t longest = 120;
        if (out.name.size() + suffix.size() > longest) {
            char hash[20];
            std::snprintf(hash, sizeof hash, "_%016llx", static_cast<unsigned long long>(fnv1a_64(others)));
            suffix = suffix.substr(0, longest - std::min(longest, out.name.size() + 17)) + hash;
        }
        out.name += suffix;
    }
    return out;
}

std::string ioh_fixed(double value) {
    char buffer[400]; // %.10f of the largest double is 309 + 11 characters
    std::snprintf(buffer, sizeof buffer, "%.10f", value);
    return buffer;
}

std::string ioh_shortest(double value) {
    if (!std::isfinite(value))
        return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
    // The shortest digits that read back to `value`, as d.ddde+XX.
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific).ptr;
    std::string text(buffer, end);
    std::string sign;
    if (text[0] == '-') {
        sign = "-";
        text.erase(0, 1);
    }
    const auto e = text.find('e');
    int exponent = 0;
    std::from_chars(text.data() + e + 1 + (text[e + 1] == '+' ? 1 : 0), text.data() + text.size(), exponent);
    std::string digits = text.substr(0, e);
    digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
    const auto n = static_cast<int>(digits.size());
    if (exponent < -4 || exponent >= 16) { // fmt's exponent notation, at least two exponent digits
        char exp_text[16];
        std::snprintf(exp_text, sizeof exp_text, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
        return sign + digits.substr(0, 1) + (n > 1 ? "." + digits.substr(1) : "") + exp_text;
    }
    if (exponent < 0)
        return sign + "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    const int integer_digits = exponent + 1;
    if (n <= integer_digits)
        return sign + digits + std::string(static_cast<std::size_t>(integer_digits - n), '0');
    return sign + digits.substr(0, static_cast<std::size_t>(integer_digits)) + "." +
           digits.substr(static_cast<std::size_t>(integer_digits));
}

namespace {

// Every problem's function, with ids made distinct across the whole export (so that every
// algorithm folder numbers a function alike): a name meeting another on an id takes the next free
// one, in (id, name) order.
std::map<std::string, IohFunction> distinct_functions(const StudyIndex& index) {
    std::map<std::string, IohFunction> functions; // by problem spec
    std::set<std::pair<int, std::string>> wanted;
    for (const auto& problem : index.problems()) {
        functions[problem] = ioh_function(problem);
        wanted.emplace(functions[problem].id, functions[problem].name);
    }
    std::map<std::string, int> id_of_name;
    std::set<int> taken;
    for (const auto& [id, name] : wanted) {
        int free_id = id;
        while (taken.count(free_id) != 0)
            ++free_id;
        taken.insert(free_id);
        id_of_name[name] = free_id;
    }
    for (auto& [problem, function] : functions)
        function.id = id_of_name[function.name];
    return functions;
}

// Adds the runs of `group`, of a problem that is `function`, to the scenarios of `fx`, by dimension
// (problems differing in instance or dimension only are one function); a run without a finite
// value is only counted.
void add_runs(const RunGroup& group, const IohFunction& function, FunctionExport& fx,
              IohExportSummary& summary) {
    for (const RunRecord* r : group.runs) {
        const double shift = function.minus_f_opt && r->f_opt ? *r->f_opt : 0.0;
        ExportedRun run = r->improvements ? exact_rows(*r, shift) : grid_rows(*r, shift);
        if (run.rows.empty()) { // no improvement: every f was +inf
            ++summary.runs_left_out;
            continue;
        }
        if (!r->improvements)
            ++fx.approximate_runs;
        run.instance = function.instance;
        const std::size_t dimension =
            !r->best_x.empty() ? r->best_x.size() : static_cast<std::size_t>(function.dimension.value_or(0));
        auto scenario = std::find_if(fx.scenarios.begin(), fx.scenarios.end(),
                                     [&](const Scenario& s) { return s.dimension == dimension; });
        if (scenario == fx.scenarios.end()) {
            fx.scenarios.push_back({dimension, {}});
            scenario = fx.scenarios.end() - 1;
        }
        scenario->runs.push_back(std::move(run));
    }
}

// An algorithm's functions in order of first appearance, each with its scenarios.
std::vector<FunctionExport> algorithm_exports(const StudyIndex& index, const std::string& algorithm,
                                              const std::map<std::string, IohFunction>& functions,
                                              IohExportSummary& summary) {
    std::vector<FunctionExport> exports;
    for (const auto& problem : index.problems()) {
        const RunGroup* group = index.find(problem, algorithm);
        if (group == nullptr)
            continue;
        const IohFunction& function = functions.at(problem);
        auto fx = std::find_if(exports.begin(), exports.end(),
                               [&](const FunctionExport& e) { return e.function.id == function.id; });
        if (fx == exports.end()) {
            exports.push_back({function, {}, 0});
            fx = exports.end() - 1;
        }
        add_runs(*group, function, *fx, summary);
    }
    return exports;
}

// Writes the .dat of a scenario of function `id` into folder/data_folder and returns the
// scenario's entry of the JSON.
std::string write_scenario(const fs::path& folder, const std::string& data_folder, const std::string& id,
                           const Scenario& scenario, IohPrecision precision, IohExportSummary& summary) {
    const std::string dat_path =
        data_folder + "/IOHprofiler_f" + id + "_DIM" + std::to_string(scenario.dimension) + ".dat";
    std::string dat;
    std::vector<std::string> runs;
    for (const ExportedRun& run : scenario.runs) {
        dat += "evaluations raw_y\n";
        for (const Row& row : run.rows)
            dat += std::to_string(row.evaluations) + ' ' + dat_value(row.y, precision, summary.none_values) +
                   '\n';
        std::string x;
        for (std::size_t k = 0; k < run.record->best_x.size(); ++k)
            x += (k == 0 ? "" : ", ") + json_number(run.record->best_x[k]);
        runs.push_back("\"instance\": " + std::to_string(run.instance) +
                       ", \"evals\": " + std::to_string(run.record->evaluations) +
                       ", \"best\": {\"evals\": " + std::to_string(run.best_evaluations) +
                       ", \"y\": " + json_number(run.best_y) + ", \"x\": [" + x + "]}");
    }
    fs::create_directories(folder / data_folder);
    write_file_atomically(folder / dat_path, dat);
    ++summary.files;
    std::string joined;
    for (std::size_t i = 0; i < runs.size(); ++i)
        joined += (i == 0 ? "" : "},\n\t\t\t{") + runs[i];
    return "\"dimension\": " + std::to_string(scenario.dimension) +
           ",\n\t\t\"path\": " + json_string(dat_path) + ",\n\t\t\"runs\": [\n\t\t\t{" + joined + "}\n\t\t]";
}

// The JSON of one function of an algorithm, in IOH's layout (to the spaces before its line breaks).
std::string function_json(const StudyIndex& index, const std::string& algorithm, const FunctionExport& fx,
                          const std::vector<std::string>& scenarios) {
    std::string info = "mhbench " + index.full_spec(algorithm);
    if (!index.budget().empty())
        info += ", budget " + index.budget();
    if (fx.approximate_runs > 0)
        info += "; " + std::to_string(fx.approximate_runs) + (fx.approximate_runs == 1 ? " run" : " runs") +
                " stored before mhbench recorded improvements: rows where its trace recorded them "
                "(iteration ends, log grid), not at each improvement";
    std::string joined;
    for (std::size_t i = 0; i < scenarios.size(); ++i)
        joined += (i == 0 ? "" : "},\n\t\t{") + scenarios[i];
    return std::string("{\n\t\"version\": \"") + ioh_format_version +
           "\", \n\t\"suite\": " + json_string(fx.function.suite) +
           ", \n\t\"function_id\": " + std::to_string(fx.function.id) +
           ", \n\t\"function_name\": " + json_string(fx.function.name) +
           ", \n\t\"maximization\": false, \n\t\"algorithm\": {\"name\": " +
           json_string(index.label(algorithm)) + ", \"info\": " + json_string(info) +
           "},\n\t\"attributes\": [\"evaluations\", \"raw_y\"],\n\t\"scenarios\": [\n\t\t{" + joined +
           "}\n\t]\n}\n";
}

// The files of one function of an algorithm in `folder`: a .dat per scenario and the JSON.
void write_function(const StudyIndex& index, const std::string& algorithm, const fs::path& folder,
                    const FunctionExport& fx, IohPrecision precision, IohExportSummary& summary) {
    summary.approximate_runs += fx.approximate_runs;
    const std::string id = std::to_string(fx.function.id);
    const std::string data_folder = "data_f" + id + "_" + fx.function.name;
    std::vector<std::string> scenarios;
    for (const Scenario& scenario : fx.scenarios)
        scenarios.push_back(write_scenario(folder, data_folder, id, scenario, precision, summary));
    write_file_atomically(folder / ("IOHprofiler_f" + id + "_" + fx.function.name + ".json"),
                          function_json(index, algorithm, fx, scenarios));
    ++summary.files;
}

} // namespace

IohExportSummary write_ioh_export(const StudyIndex& index, const fs::path& dir, IohPrecision precision) {
    IohExportSummary summary;
    remove_earlier_export(dir);
    const std::map<std::string, IohFunction> functions = distinct_functions(index);
    for (const auto& algorithm : index.algorithms()) {
        const fs::path folder = dir / file_name_part(algorithm);
        for (const FunctionExport& fx : algorithm_exports(index, algorithm, functions, summary))
            if (!fx.scenarios.empty())
                write_function(index, algorithm, folder, fx, precision, summary);
    }
    return summary;
}

} // namespace mhb
