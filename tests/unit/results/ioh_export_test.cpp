// The IOHprofiler export's rules: IOH's number formats, how problems become IOH functions (stable
// ids, never by study order), the rows of a run (improvements, the last evaluation, None), runs
// stored before improvements were recorded, and what an earlier export left behind.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <set>
#include <sstream>

#include "results/exports/ioh_export.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

namespace fs = std::filesystem;

using mhb::test_support::inf;

fs::path fresh_ioh_export_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_ioh_export_" + name);
    fs::remove_all(dir);
    return dir;
}

std::string read_existing_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << path;
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

TEST(IohExport, NumbersAreFormattedAsFmtFormatsThemForIoh) {
    // Expected texts: fmt 9's format("{}") and format("{:.10f}") of the same doubles.
    const std::pair<double, const char*> shortest[] = {{0.0, "0"},
                                                       {-0.0, "-0"},
                                                       {5.0, "5"},
                                                       {0.1, "0.1"},
                                                       {1e-4, "0.0001"},
                                                       {1e-5, "1e-05"},
                                                       {123456789012345.0, "123456789012345"},
                                                       {1234567890123456.0, "1234567890123456"},
                                                       {1e16, "1e+16"},
                                                       {1.5e17, "1.5e+17"},
                                                       {0.00012345, "0.00012345"},
                                                       {2.5e-300, "2.5e-300"},
                                                       {1e300, "1e+300"},
                                                       {-3.25, "-3.25"},
                                                       {100000.0, "100000"},
                                                       {1e21, "1e+21"},
                                                       {0.3666750800000002, "0.3666750800000002"},
                                                       {1719.6920237276904, "1719.6920237276904"}};
    for (const auto& [value, text] : shortest)
        EXPECT_EQ(ioh_shortest(value), text) << text;
    EXPECT_EQ(ioh_fixed(0.3666750800000002), "0.3666750800");
    EXPECT_EQ(ioh_fixed(1719.6920237276904), "1719.6920237277");
    EXPECT_EQ(ioh_fixed(2.5e-300), "0.0000000000");
    EXPECT_EQ(ioh_fixed(-3.25), "-3.2500000000");
    EXPECT_EQ(ioh_fixed(1e21), "1000000000000000000000.0000000000");
}

TEST(IohExport, BbobProblemsAreIohsBbobFunctions) {
    const IohFunction f8 = ioh_function("bbob:dim=5,f=8,instance=3");
    EXPECT_EQ(f8.suite, "BBOB");
    EXPECT_EQ(f8.id, 8);
    EXPECT_EQ(f8.name, "Rosenbrock");
    EXPECT_EQ(f8.instance, 3);
    EXPECT_EQ(f8.dimension, 5);
    EXPECT_TRUE(f8.minus_f_opt);
    const char* names[] = {
        "Sphere",           "Ellipsoid",     "Rastrigin",     "BuecheRastrigin",    "LinearSlope",
        "AttractiveSector", "StepEllipsoid", "Rosenbrock",    "RosenbrockRotated",  "EllipsoidRotated",
        "Discus",           "BentCigar",     "SharpRidge",    "DifferentPowers",    "RastriginRotated",
        "Weierstrass",      "Schaffers10",   "Schaffers1000", "GriewankRosenbrock", "Schwefel",
        "Gallagher101",     "Gallagher21",   "Katsuura",      "LunacekBiRastrigin"};
    for (int f = 1; f <= 24; ++f) {
        const IohFunction function = ioh_function("bbob:dim=2,f=" + std::to_string(f) + ",instance=1");
        EXPECT_EQ(function.id, f);
        EXPECT_EQ(function.name, names[f - 1]);
    }
    // Defaults, as the bbob family declares them: f 1, instance 1.
    EXPECT_EQ(ioh_function("bbob:dim=3").id, 1);
    EXPECT_EQ(ioh_function("bbob:dim=3").instance, 1);
}

TEST(IohExport, OtherFamiliesHaveFixedIdsAndParametersMakeDistinctStableFunctions) {
    const IohFunction sphere = ioh_function("sphere:dim=10");
    EXPECT_EQ(sphere.suite, "mhbench");
    EXPECT_EQ(sphere.id, 101);
    EXPECT_EQ(sphere.name, "sphere");
    EXPECT_FALSE(sphere.minus_f_opt);
    EXPECT_EQ(ioh_function("rastrigin:dim=2").id, 110);
    EXPECT_EQ(ioh_function("penalized_2:dim=3,instance=7").id, 117);
    EXPECT_EQ(ioh_function("penalized_2:dim=3,instance=7").instance, 7);
    EXPECT_EQ(ioh_function("pmsm").id, 200);

    // Other parameters: a name that shows them and an id from their hash, the same in any study.
    const IohFunction shifted = ioh_function("rastrigin:dim=10,instance=2,shift=on");
    EXPECT_EQ(shifted.name, "rastrigin_shift_on");
    EXPECT_EQ(shifted.instance, 2);
    EXPECT_EQ(shifted.id / 1000000, 110);
    const IohFunction paper = ioh_function("pmsm:load=2,speed=2500");
    EXPECT_EQ(paper.name, "pmsm_load_2_speed_2500");
    EXPECT_EQ(paper.instance, 1);
    EXPECT_EQ(paper.id / 1000000, 200);
    EXPECT_EQ(paper.id, 200777259); // fixed for good: a change here renumbers users' data
    EXPECT_EQ(shifted.id, 110658275);
    std::set<int> ids;
    for (const char* spec : {"pmsm:load=2,speed=2500", "pmsm:load=3,speed=2500", "pmsm:load=2,speed=2000",
                             "pmsm:load=2,model=dynamic,speed=2500", "pmsm", "sphere:dim=2",
                             "sphere:dim=2,shift=on", "sphere:dim=2,rotate=on,shift=on"})
        ids.insert(ioh_function(spec).id);
    EXPECT_EQ(ids.size(), 8u);
    // Dimension and instance are IOH's own fields, not parts of the function.
    EXPECT_EQ(ioh_function("sphere:dim=5,instance=3").id, ioh_function("sphere:dim=20").id);

    // A family the table does not know gets an id in 300-999; a long list of parameters a short name.
    const int other = ioh_function("myfamily:dim=3").id;
    EXPECT_GE(other, 300);
    EXPECT_LE(other, 999);
    const IohFunction long_name = ioh_function("pmsm:data=" + std::string(300, 'a') + ".csv");
    EXPECT_LE(long_name.name.size(), 120u);
    EXPECT_NE(long_name.name, ioh_function("pmsm:data=" + std::string(300, 'a') + "b.csv").name);
}

RunRecord ioh_run(std::int64_t id, const std::string& algorithm, const std::string& problem,
                  std::int64_t index, double best_f, std::int64_t evaluations) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = "evaluations=10";
    r.run_index = index;
    r.seed = static_cast<std::uint64_t>(index + 1);
    r.best_f = best_f;
    r.best_x = {0.25, -1.5};
    r.evaluations = evaluations;
    r.iterations = 1;
    return r;
}

TEST(IohExport, RowsAreTheImprovementsAndTheLastEvaluation) {
    StudyData data;
    // An improvement at 1, 4 and 6, then the last evaluation (10) with its own f.
    RunRecord a = ioh_run(0, "de", "sphere:dim=2", 0, 0.5, 10);
    a.improvements = ImprovementTrace{{{1, 10.0}, {4, 2.5}, {6, 0.5}}, 3.0};
    // The last evaluation is the last improvement: no extra row.
    RunRecord b = ioh_run(1, "de", "sphere:dim=2", 1, 0.25, 10);
    b.improvements = ImprovementTrace{{{1, 7.0}, {10, 0.25}}, 0.25};
    // The last evaluation at +inf: None, as IOH writes it.
    RunRecord c = ioh_run(2, "de", "sphere:dim=2", 2, 1.0, 10);
    c.improvements = ImprovementTrace{{{2, 1.0}}, inf};
    // Never a finite value: left out.
    RunRecord d = ioh_run(3, "de", "sphere:dim=2", 3, inf, 10);
    d.improvements = ImprovementTrace{{}, inf};
    // BBOB: raw_y is f - f_opt.
    RunRecord e = ioh_run(4, "de", "bbob:dim=2,f=1,instance=2", 0, 80.48, 5);
    e.f_opt = 79.48;
    e.improvements = ImprovementTrace{{{1, 90.48}, {3, 80.48}}, 85.0};
    data.runs = {a, b, c, d, e};

    const fs::path dir = fresh_ioh_export_dir("rows");
    const IohExportSummary summary = write_ioh_export(StudyIndex(data), dir);
    EXPECT_EQ(summary.runs_left_out, 1u);
    EXPECT_EQ(summary.none_values, 1u);
    EXPECT_EQ(summary.approximate_runs, 0u);
    EXPECT_EQ(summary.files, 4u);
    EXPECT_EQ(read_existing_text(dir / "de" / "data_f101_sphere" / "IOHprofiler_f101_DIM2.dat"),
              "evaluations raw_y\n1 10.0000000000\n4 2.5000000000\n6 0.5000000000\n10 3.0000000000\n"
              "evaluations raw_y\n1 7.0000000000\n10 0.2500000000\n"
              "evaluations raw_y\n2 1.0000000000\n10 None\n");
    EXPECT_EQ(
        read_existing_text(dir / "de" / "IOHprofiler_f101_sphere.json"),
        "{\n\t\"version\": \"0.3.23\", \n\t\"suite\": \"mhbench\", \n\t\"function_id\": 101, "
        "\n\t\"function_name\": \"sphere\", \n\t\"maximization\": false, "
        "\n\t\"algorithm\": {\"name\": \"de\", \"info\": \"mhbench de, budget evaluations=10\"},"
        "\n\t\"attributes\": [\"evaluations\", \"raw_y\"],\n\t\"scenarios\": [\n\t\t{\"dimension\": 2,"
        "\n\t\t\"path\": \"data_f101_sphere/IOHprofiler_f101_DIM2.dat\",\n\t\t\"runs\": [\n"
        "\t\t\t{\"instance\": 1, \"evals\": 10, \"best\": {\"evals\": 6, \"y\": 0.5, \"x\": [0.25, -1.5]}},\n"
        "\t\t\t{\"instance\": 1, \"evals\": 10, \"best\": {\"evals\": 10, \"y\": 0.25, \"x\": [0.25, "
        "-1.5]}},\n"
        "\t\t\t{\"instance\": 1, \"evals\": 10, \"best\": {\"evals\": 2, \"y\": 1, \"x\": [0.25, -1.5]}}"
        "\n\t\t]}\n\t]\n}\n");
    EXPECT_EQ(read_existing_text(dir / "de" / "data_f1_Sphere" / "IOHprofiler_f1_DIM2.dat"),
              "evaluations raw_y\n1 11.0000000000\n3 1.0000000000\n5 5.5200000000\n");
    const std::string bbob = read_existing_text(dir / "de" / "IOHprofiler_f1_Sphere.json");
    EXPECT_NE(bbob.find("\"suite\": \"BBOB\""), std::string::npos) << bbob;
    EXPECT_NE(bbob.find("{\"instance\": 2, \"evals\": 5, \"best\": {\"evals\": 3, \"y\": 1, \"x\""),
              std::string::npos)
        << bbob;
}

// --ioh-precision full: raw_y with every digit, where the logger's %.10f reads tiny errors as 0.
TEST(IohExport, FullPrecisionKeepsEveryDigitOfRawY) {
    StudyData data;
    RunRecord a = ioh_run(0, "de", "sphere:dim=2", 0, 3.1e-12, 10);
    a.improvements = ImprovementTrace{{{1, 10.0}, {4, 2.9e-9}, {6, 3.1e-12}}, 0.125};
    RunRecord b = ioh_run(1, "de", "sphere:dim=2", 1, 1.0, 10);
    b.improvements = ImprovementTrace{{{2, 1.0}}, inf};
    data.runs = {a, b};
    const fs::path logger = fresh_ioh_export_dir("precision_logger");
    const fs::path full = fresh_ioh_export_dir("precision_full");
    (void)write_ioh_export(StudyIndex(data), logger);
    const IohExportSummary summary = write_ioh_export(StudyIndex(data), full, IohPrecision::full);
    EXPECT_EQ(summary.none_values, 1u);
    const fs::path dat = fs::path("de") / "data_f101_sphere" / "IOHprofiler_f101_DIM2.dat";
    EXPECT_EQ(read_existing_text(logger / dat),
              "evaluations raw_y\n1 10.0000000000\n4 0.0000000029\n6 0.0000000000\n"
              "10 0.1250000000\nevaluations raw_y\n2 1.0000000000\n10 None\n");
    EXPECT_EQ(read_existing_text(full / dat),
              "evaluations raw_y\n1 10\n4 2.9e-09\n6 3.1e-12\n10 0.125\nevaluations raw_y\n2 1\n10 None\n");
    // The JSON is the same either way.
    EXPECT_EQ(read_existing_text(logger / "de" / "IOHprofiler_f101_sphere.json"),
              read_existing_text(full / "de" / "IOHprofiler_f101_sphere.json"));
}

TEST(IohExport, RunsWithoutImprovementsUseTheirGridAndSaySo) {
    StudyData data;
    RunRecord old = ioh_run(0, "pso", "pmsm:load=2,speed=2500", 0, 4.0, 1200);
    old.best_x = {0.3, 0.003, 0.003, 0.07};
    old.curve = {{0, 50, 16.0, {}}, {1, 100, 8.0, {}}, {2, 150, 8.0, {}}};
    old.checkpoints = {{1, 32.0}, {10, 16.0}, {100, 8.0}, {1200, 4.0}};
    data.runs = {old};
    const fs::path dir = fresh_ioh_export_dir("grid");
    const IohExportSummary summary = write_ioh_export(StudyIndex(data), dir);
    EXPECT_EQ(summary.approximate_runs, 1u);
    const IohFunction f = ioh_function(old.problem);
    const std::string stem = std::to_string(f.id) + "_" + f.name;
    EXPECT_EQ(read_existing_text(dir / "pso" / ("data_f" + stem) /
                                 ("IOHprofiler_f" + std::to_string(f.id) + "_DIM4.dat")),
              "evaluations raw_y\n1 32.0000000000\n10 16.0000000000\n100 8.0000000000\n1200 4.0000000000\n");
    const std::string json = read_existing_text(dir / "pso" / ("IOHprofiler_f" + stem + ".json"));
    EXPECT_NE(json.find("1 run stored before mhbench recorded improvements"), std::string::npos) << json;
    EXPECT_NE(json.find("\"best\": {\"evals\": 1200, \"y\": 4,"), std::string::npos) << json;
}

TEST(IohExport, IdsThatMeetAreMadeDistinctAndEveryAlgorithmNumbersAlike) {
    StudyData data;
    data.runs = {ioh_run(0, "a", "sphere:dim=2", 0, 1.0, 10),
                 ioh_run(1, "b", "pmsm:load=2,speed=2500", 0, 1.0, 10),
                 ioh_run(2, "a", "pmsm:load=2,speed=2500", 0, 1.0, 10)};
    for (auto& r : data.runs)
        r.improvements = ImprovementTrace{{{1, 1.0}}, 1.0};
    const fs::path dir = fresh_ioh_export_dir("ids");
    write_ioh_export(StudyIndex(data), dir);
    const std::string name = "IOHprofiler_f200777259_pmsm_load_2_speed_2500.json";
    EXPECT_TRUE(fs::exists(dir / "a" / name));
    EXPECT_TRUE(fs::exists(dir / "b" / name));
    EXPECT_TRUE(fs::exists(dir / "a" / "IOHprofiler_f101_sphere.json"));
}

TEST(IohExport, WhatAnEarlierExportLeftIsRemovedAndNothingElse) {
    const fs::path dir = fresh_ioh_export_dir("stale");
    fs::create_directories(dir / "old_algorithm" / "data_f4_sphere_dim_2");
    std::ofstream(dir / "old_algorithm" / "IOHprofiler_f4_sphere_dim_2.json") << "{}";
    std::ofstream(dir / "old_algorithm" / "data_f4_sphere_dim_2" / "IOHprofiler_f4_DIM2.dat") << "x";
    fs::create_directories(dir / "mine");
    std::ofstream(dir / "mine" / "notes.txt") << "kept";
    StudyData data;
    data.runs = {ioh_run(0, "de", "sphere:dim=2", 0, 1.0, 10)};
    data.runs[0].improvements = ImprovementTrace{{{1, 1.0}}, 1.0};
    write_ioh_export(StudyIndex(data), dir);
    EXPECT_FALSE(fs::exists(dir / "old_algorithm"));
    EXPECT_TRUE(fs::exists(dir / "mine" / "notes.txt"));
    EXPECT_TRUE(fs::exists(dir / "de" / "IOHprofiler_f101_sphere.json"));
}

} // namespace
} // namespace mhb
