// Export of a study's runs in the IOHprofiler format, exactly as IOHexperimenter's analyzer logger
// (ioh::logger::Analyzer, v0.3.x, with its default trigger on_improvement and properties
// evaluations and raw_y) writes it, so that IOHanalyzer loads it and merges it with data IOH wrote
// itself. tests/data/ioh/ holds a sample IOHexperimenter wrote and its README. Per algorithm:
//   <dir>/<algorithm>/IOHprofiler_f<id>_<name>.json             one per function: the JSON below
//   <dir>/<algorithm>/data_f<id>_<name>/IOHprofiler_f<id>_DIM<d>.dat   one per dimension
// The JSON, with IOH's layout, key order and spacing: version (of the IOHexperimenter whose output
// this reproduces), suite, function_id, function_name, maximization, algorithm {name: the label,
// info: the full spec and budget}, attributes ["evaluations", "raw_y"], and scenarios, one per
// dimension in order of first appearance: dimension, path of its .dat, and runs {instance, evals
// (all the run's evaluations), best {evals (the evaluation of its best), y, x}}.
// The .dat: for each run, in the JSON's order, the header "evaluations raw_y", then a row at every
// strict improvement of best-so-far f (the evaluation that made it; the first f below +inf is
// one), then, when the last evaluation was not an improvement, a row for it with its own f
// (not the best), as IOH's logger writes on closing a run. raw_y is printed "%.10f", as IOH does;
// the JSON's numbers in fmt's shortest form ({}), as IOH does.
//
// Functions, instances, dimensions (a problem spec is split into name and parameters):
//   - bbob: suite "BBOB", function_id = f (1-24), function_name IOH's ("Sphere", "Ellipsoid",
//     "Rastrigin", ... "LunacekBiRastrigin"), instance = instance, dimension = dim. raw_y is
//     f - f_opt: IOH's BBOB problems log the value before their objective transformation adds
//     COCO's f_opt, which our bbob problems include.
//   - the classic functions: suite "mhbench", function_id 101-117 by a fixed table of their names
//     (sphere 101, ellipsoid 102, schwefel_1_2 103, schwefel_2_21 104, schwefel_2_22 105, step
//     106, quartic 107, rosenbrock 108, zakharov 109, rastrigin 110, ackley 111, griewank 112,
//     schwefel_2_26 113, levy 114, weierstrass 115, penalized_1 116, penalized_2 117), name as in
//     mhbench, instance = instance (default 1), dimension = dim. raw_y is f.
//   - pmsm: suite "mhbench", function_id 200, name "pmsm", instance 1; raw_y is f.
//   - any other family: function_id 300 + (FNV-1a hash of its name mod 700).
//   Parameters other than dim and instance (bbob: also f) make distinct functions: the name gets
//   "_<key>_<value>" for each, in key order ("pmsm_load_2_speed_2500"), and the id becomes
//   base * 10^6 + 1 + (FNV-1a hash of the key=value text mod 999999), so one problem gets one id
//   in every study, on every platform (FNV-1a 64, problems/core/fnv1a.hpp; a
//   name cut for length ends in that hash in hex). Two names of one export meeting on an id
//   (about 1 in 10^6 per pair) are resolved by giving the later name, in (id, name) order, the
//   next free id.
//   The dimension is the length of the runs' best x. Never numbered by study order.
//
// Runs stored before mhbench recorded improvements (RunRecord::improvements empty) have rows at
// the improvements mhbench recorded then (ends of iterations and the log grid of evaluation
// counts), each at the evaluation where it was recorded, which can be later than where it
// happened; they are counted (approximate_runs) and the algorithm's "info" says so.
// Non-finite values: a raw_y that is not finite is written "None", IOH's mark for no value (only
// -inf improvements and a last evaluation at +inf); a run that never had a finite value (it ended
// at +inf) is left out of the export, as IOH leaves out a run without an improvement; in the JSON
// (which has no inf) such a y or coordinate of x is null. Failed runs are never exported.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// The IOHexperimenter version whose analyzer output the export reproduces.
inline constexpr const char* ioh_format_version = "0.3.23";

// Where a problem spec goes in IOH's terms (before collisions of ids are resolved).
struct IohFunction {
    std::string suite;
    int id = 0;
    std::string name;
    std::int64_t instance = 1;
    std::optional<std::int64_t> dimension; // from the spec's dim, if it has one
    bool minus_f_opt = false;              // raw_y = f - f_opt (BBOB)
};
IohFunction ioh_function(const std::string& problem_spec);

// IOH's number formats: raw_y in the .dat ("{:.10f}") and numbers in the JSON (fmt's "{}", the
// shortest text that reads back to the same double, in fixed notation for decimal exponents in
// [-4, 16) and d.ddde+XX otherwise).
std::string ioh_fixed(double value);
std::string ioh_shortest(double value);

struct IohExportSummary {
    std::size_t files = 0;            // files written
    std::size_t runs_left_out = 0;    // runs without a finite value (ended at +inf)
    std::size_t none_values = 0;      // raw_y written "None" (not finite)
    std::size_t approximate_runs = 0; // runs stored without improvements: rows from the grid
};

// How raw_y is written in the .dat files. `logger`: "%.10f", byte for byte what IOHexperimenter's
// logger writes (every error below 5e-11 reads 0). `full`: the shortest text that reads back to
// the same double (ioh_shortest, the JSON's format), which IOHanalyzer's reader also takes (it
// reads every column as text and converts it with as.numeric), for errors down to 1e-300.
enum class IohPrecision { logger, full };

// Writes the export under `dir`, after removing what an earlier export left there (IOH files and
// data folders in its algorithm folders, which IOHanalyzer would otherwise load too).
IohExportSummary write_ioh_export(const StudyIndex& index, const std::filesystem::path& dir,
                                  IohPrecision precision = IohPrecision::logger);

} // namespace mhb
