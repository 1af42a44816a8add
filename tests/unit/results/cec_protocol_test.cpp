// The CEC protocols' recording on hand-made run records (no optimiser involved): the checkpoints of
// CEC 2017 (fractions of MaxFES) and CEC 2022 (floor(D^(k/5 - 3) MaxFES), worked out with 50-digit
// decimals), the 1e-8 rule (an error of 5e-9 is written 0, one of exactly 1e-8 is kept), errors read
// exactly from the improvements at any evaluation count, FEterm, the organisers' matrix, the
// evaluation budgets that depend on the dimension, and the `protocol =` line of a study.ini.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

#include "results/analysis/cec_protocol.hpp"
#include "results/analysis/dimension_budget.hpp"
#include "results/exports/cec_result_files.hpp"

namespace mhb {
namespace {

// A run on a problem with f* = 300 whose best-so-far improves at evaluations 1, 40, 250 and 900,
// the last to an error of 5e-9, if it ran that far: it ran `evaluations` evaluations in all.
RunRecord improving_run(std::int64_t evaluations) {
    RunRecord r;
    r.problem = "cec2017:dim=10,f=3";
    r.f_opt = 300.0;
    r.evaluations = evaluations;
    r.improvements = ImprovementTrace{};
    for (const CheckpointSample& p : std::vector<CheckpointSample>{
             {1, 300.0 + 5000.0}, {40, 300.0 + 70.0}, {250, 300.0 + 0.25}, {900, 300.0 + 5e-9}})
        if (p.evaluations <= evaluations)
            r.improvements->points.push_back(p);
    r.best_f = r.improvements->points.back().best_f;
    r.best_x.assign(10, 0.0);
    return r;
}

TEST(CecProtocol, BothProtocolsAreKnownByName) {
    ASSERT_NE(find_cec_protocol("cec2017"), nullptr);
    ASSERT_NE(find_cec_protocol("cec2022"), nullptr);
    EXPECT_EQ(find_cec_protocol("cec2014"), nullptr);
    EXPECT_EQ(cec_protocol_names(), "cec2017, cec2022");
    EXPECT_EQ(find_cec_protocol("cec2017")->runs, 51);
    EXPECT_EQ(find_cec_protocol("cec2022")->runs, 30);
    EXPECT_EQ(find_cec_protocol("cec2017")->family, "cec2017");
}

TEST(CecProtocol, Cec2017RecordsFourteenFractionsOfMaxFes) {
    const CecProtocol& p = *find_cec_protocol("cec2017");
    // MaxFES = 10000 x D at D = 30.
    EXPECT_EQ(p.checkpoints(300000, 30),
              (std::vector<std::int64_t>{3000, 6000, 9000, 15000, 30000, 60000, 90000, 120000, 150000, 180000,
                                         210000, 240000, 270000, 300000}));
    EXPECT_EQ(p.row_names().size(), 14u);
    EXPECT_EQ(p.row_names().front(), "0.01 x MaxFES");
    EXPECT_EQ(p.row_names().back(), "1 x MaxFES");
}

TEST(CecProtocol, Cec2022RecordsSixteenPowersOfDAndFeTerm) {
    const CecProtocol& p = *find_cec_protocol("cec2022");
    // floor(D^(k/5 - 3) MaxFES), k = 0..15, computed with 50-digit decimals: exact products such as
    // 20^-2 x 1e6 = 2500 must not be floored to 2499.
    EXPECT_EQ(p.checkpoints(200000, 10),
              (std::vector<std::int64_t>{200, 316, 502, 796, 1261, 2000, 3169, 5023, 7962, 12619, 20000,
                                         31697, 50237, 79621, 126191, 200000}));
    EXPECT_EQ(p.checkpoints(1000000, 20),
              (std::vector<std::int64_t>{125, 227, 414, 754, 1373, 2500, 4551, 8286, 15085, 27464, 50000,
                                         91028, 165722, 301708, 549280, 1000000}));
    EXPECT_EQ(p.row_names().size(), 17u);
    EXPECT_EQ(p.row_names().back().rfind("FEterm", 0), 0u);
    // A budget far below the protocol's never asks for the error after 0 evaluations.
    EXPECT_EQ(p.checkpoints(5000, 20).front(), 1);
}

TEST(CecProtocol, ErrorsBelow1e8AreZero) {
    EXPECT_EQ(cec_error(300.0 + 5e-9, 300.0), 0.0);
    EXPECT_EQ(cec_error(100.0 - 1e-12, 100.0), 0.0); // below f* by rounding
    EXPECT_EQ(cec_error(1e-8, 0.0), 1e-8);           // not below: kept
    EXPECT_EQ(cec_error(302.5, 300.0), 2.5);
    EXPECT_TRUE(std::isnan(cec_error(std::numeric_limits<double>::quiet_NaN(), 1.0)));
    EXPECT_EQ(cec_error(std::numeric_limits<double>::infinity(), 1.0),
              std::numeric_limits<double>::infinity());
}

TEST(CecProtocol, ErrorsAtAnyEvaluationComeFromTheImprovements) {
    const RunRecord r = improving_run(1000);
    EXPECT_EQ(cec_error_at(r, 1), 5000.0);
    EXPECT_EQ(cec_error_at(r, 39), 5000.0);
    EXPECT_EQ(cec_error_at(r, 40), 70.0);
    EXPECT_EQ(cec_error_at(r, 249), 70.0);
    EXPECT_EQ(cec_error_at(r, 250), 0.25);
    EXPECT_EQ(cec_error_at(r, 899), 0.25);
    EXPECT_EQ(cec_error_at(r, 900), 0.0); // 5e-9: below 1e-8
    EXPECT_EQ(cec_error_at(r, 1000), 0.0);
    // A run that stopped (its target reached) counts with its final value afterwards.
    EXPECT_EQ(cec_error_at(improving_run(900), 5000), 0.0);
    RunRecord unknown = r;
    unknown.f_opt.reset();
    EXPECT_TRUE(std::isnan(cec_error_at(unknown, 500)));
}

TEST(CecProtocol, FeTermIsTheFirstEvaluationBelow1e8) {
    EXPECT_EQ(cec_termination_evaluations(improving_run(1000), 1000), 900);
    EXPECT_EQ(cec_termination_evaluations(improving_run(800), 800), 800); // never below: MaxFES
    // Runs stored before improvements were recorded: the first recorded point below 1e-8.
    RunRecord old = improving_run(1000);
    old.improvements.reset();
    old.curve = {{0, 50, 300.0 + 70.0, {}}, {1, 100, 300.0 + 0.25, {}}, {2, 950, 300.0 + 5e-9, {}}};
    EXPECT_EQ(cec_termination_evaluations(old, 1000), 950);
}

TEST(CecProtocol, TheOrganisersMatrixHasARowPerCheckpointAndAColumnPerRun) {
    const RunRecord a = improving_run(1000);
    RunRecord b = improving_run(1000);
    b.improvements->points = {{1, 300.0 + 8.0}, {600, 300.0 + 1.5}};
    b.best_f = 301.5;
    const std::vector<const RunRecord*> runs = {&a, &b};
    // CEC 2017 at MaxFES = 1000: evaluations 10, 20, 30, 50, 100, 200, 300, ..., 1000.
    EXPECT_EQ(cec_result_matrix(*find_cec_protocol("cec2017"), runs, 1000, 10),
              "5000 8\n5000 8\n5000 8\n70 8\n70 8\n70 8\n0.25 8\n0.25 8\n0.25 8\n0.25 1.5\n0.25 1.5\n"
              "0.25 1.5\n0 1.5\n0 1.5\n");
    // CEC 2022 at D = 10, MaxFES = 1000: evaluations 1, 1, 2, 3, 6, 10, 15, 25, 39, 63, 100, 158, 251,
    // 398, 630, 1000, then FEterm (900, and MaxFES for the run that never got below 1e-8).
    const CecProtocol& p2022 = *find_cec_protocol("cec2022");
    EXPECT_EQ(p2022.checkpoints(1000, 10),
              (std::vector<std::int64_t>{1, 1, 2, 3, 6, 10, 15, 25, 39, 63, 100, 158, 251, 398, 630, 1000}));
    EXPECT_EQ(cec_result_matrix(p2022, runs, 1000, 10),
              "5000 8\n5000 8\n5000 8\n5000 8\n5000 8\n5000 8\n5000 8\n5000 8\n5000 8\n70 8\n70 8\n70 8\n"
              "0.25 8\n0.25 8\n0.25 1.5\n0 1.5\n900 1000\n");
}

TEST(CecProtocol, FileNamesAreAlgorithmFunctionDimension) {
    EXPECT_EQ(cec_file_name("lshade", 5, 30), "lshade_5_30.txt");
    EXPECT_EQ(cec_file_name("itlbo[T+S-O+]", 1, 10), "itlbo-T+S-O+_1_10.txt");
    EXPECT_EQ(cec_file_name("my_pso", 12, 20), "my-pso_12_20.txt"); // '_' separates the three parts only
    EXPECT_EQ(cec_file_name("CMA-ES (IPOP)", 3, 10),
              "CMA-ES-IPOP_3_10.txt"); // a run of others is one dash, none at the end
}

TEST(CecProtocol, ProblemsOfTheFamilyNameTheirFunctionAndDimension) {
    const auto f = cec_function("cec2022:dim=20,f=7", "cec2022", 0);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->number, 7);
    EXPECT_EQ(f->dimension, 20);
    const auto defaults = cec_function("cec2017", "cec2017", 10); // f = 1, D from the runs
    ASSERT_TRUE(defaults);
    EXPECT_EQ(defaults->number, 1);
    EXPECT_EQ(defaults->dimension, 10);
    EXPECT_FALSE(cec_function("bbob:dim=10,f=1", "cec2017", 10));
}

TEST(CecProtocol, AStudyIniNamesItsProtocol) {
    EXPECT_EQ(study_protocol("# a study\nalgorithms = pso\nruns = 3\nprotocol = cec2022\n"), "cec2022");
    EXPECT_EQ(study_protocol("protocol=cec2017"), "cec2017");
    EXPECT_FALSE(study_protocol("algorithms = pso\nproblems = cec2017:f=1\n"));
}

TEST(DimensionBudget, ReadsNTimesDimAndAListByDimension) {
    const DimensionEvaluations per = DimensionEvaluations::parse("1e4*dim");
    EXPECT_EQ(per.text(), "10000*dim");
    EXPECT_EQ(per.at(10), 100000);
    EXPECT_EQ(per.at(100), 1000000);
    EXPECT_EQ(DimensionEvaluations::parse("dim*500").text(), "500*dim");
    const DimensionEvaluations listed = DimensionEvaluations::parse("dim20:1e6+dim10:200000");
    EXPECT_EQ(listed.text(), "dim10:200000+dim20:1000000"); // dimensions ascending
    EXPECT_EQ(listed.at(10), 200000);
    EXPECT_EQ(listed.at(20), 1000000);
    EXPECT_FALSE(listed.at(30));
    EXPECT_EQ(listed.dimensions_text(), "10, 20");
    EXPECT_TRUE(DimensionEvaluations::written_in("10000*dim"));
    EXPECT_TRUE(DimensionEvaluations::written_in("dim10:5"));
    EXPECT_FALSE(DimensionEvaluations::written_in("15050"));
    EXPECT_FALSE(DimensionEvaluations::written_in("1e5"));
    EXPECT_FALSE(DimensionEvaluations::written_in("1e+5")); // plain counts, as before
    EXPECT_FALSE(DimensionEvaluations::written_in("+5"));
}

TEST(DimensionBudget, BadFormsSayWhatIsWrongAndWhatIsAllowed) {
    const auto message = [](const std::string& value) {
        try {
            (void)DimensionEvaluations::parse(value);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string forms =
        "; write a count N, N*dim (N x the problem's dimension) or dimD:N+dimD:N+... (N "
        "at each dimension D listed), e.g. 10000*dim or dim10:200000+dim20:1000000";
    EXPECT_EQ(message("10000*D"),
              "budget: parameter 'evaluations' = 10000*D multiplies by 'D', not by dim" + forms);
    EXPECT_EQ(message("0*dim"),
              "budget: parameter 'evaluations' = 0*dim has a factor '0' that is not an integer in [1, "
              "1000000000000000]" +
                  forms);
    EXPECT_EQ(message("1.5*dim"),
              "budget: parameter 'evaluations' = 1.5*dim has a factor '1.5' that is not an "
              "integer in [1, 1000000000000000]" +
                  forms);
    EXPECT_EQ(message("dim10:200000+dim10:5"),
              "budget: parameter 'evaluations' = dim10:200000+dim10:5 lists dimension 10 twice" + forms);
    EXPECT_EQ(message("dimx:5"),
              "budget: parameter 'evaluations' = dimx:5 has a dimension 'x' that is not an integer in [1, "
              "1000000]" +
                  forms);
    EXPECT_EQ(message("dim10:lots"),
              "budget: parameter 'evaluations' = dim10:lots has a count 'lots' that is "
              "not an integer in [1, 1000000000000000]" +
                  forms);
    EXPECT_EQ(message("10:200"),
              "budget: parameter 'evaluations' = 10:200 has an item '10:200' that is not dimD:N" + forms);
    EXPECT_THROW((void)DimensionEvaluations::parse("1e15*dim").at(2), std::invalid_argument); // > 1e15
}

TEST(DimensionBudget, ABudgetTextGivesTheEvaluationsAtADimension) {
    EXPECT_EQ(budget_evaluations_at("evaluations=10000*dim,target=1e-08", 30), 300000);
    EXPECT_EQ(budget_evaluations_at("iterations=5,evaluations=dim10:200000+dim20:1000000", 20), 1000000);
    EXPECT_FALSE(budget_evaluations_at("evaluations=dim10:200000+dim20:1000000", 30));
    EXPECT_EQ(budget_evaluations_at("evaluations=15050", 4), 15050); // a plain count, whatever D
    EXPECT_FALSE(budget_evaluations_at("iterations=150", 10));
    EXPECT_FALSE(budget_evaluations_at("", 10));
}

} // namespace
} // namespace mhb
