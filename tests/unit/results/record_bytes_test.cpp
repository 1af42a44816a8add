// The bytes a run becomes, pinned: its record in store.bin and its lines in every rendered file.
// Stores and study directories outlive the code that wrote them, so a change to how the record
// codec or the CSV writer is built (issue 36: both generated from one list of run fields) must
// leave these bytes exactly as they were; the values were taken from the code before that change.
#include <bit>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <string>

#include "results/store/crc32c.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/rendered_lines.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

using mhb::test_support::inf;

// Every field set, with the values a careless format would lose or quote wrongly.
RunRecord awkward_record() {
    RunRecord r;
    r.run_id = 123456789012;
    r.algorithm = "itlbo:label=\"a, b\"";
    r.problem = "pmsm:load=2,speed=2500";
    r.budget = "iterations=150,evaluations=20000,target=1e-08";
    r.run_index = 19;
    r.seed = 0xfedcba9876543210U;
    r.best_f = 0.1 + 1.0 / 3.0;
    r.f_opt = 5e-324;
    r.x_opt = {0.365, 0.00325, -0.0};
    r.evaluations = 15050;
    r.iterations = 150;
    r.evaluations_to_target = 0;
    r.best_x = {0.36, inf, -0.0, 1.0 / 3.0};
    r.parameter_names = {"Rs", "Ld", "psi"};
    r.true_parameters = {0.365, 0.0, 0.0776};
    r.curve = {{0, 50, 2.0, {0.3, 0.002, 0.07}}, {1, 100, 1.0, {}}, {2, 150, -inf, {0.36, 0.003, 0.08}}};
    r.checkpoints = {{1, 9.0}, {100, std::numeric_limits<double>::quiet_NaN()}};
    r.improvements = ImprovementTrace{{{1, 9.0}, {40, 2.0}}, 0.5};
    r.message = "kept, though \"ok\"\nwith a newline";
    return r;
}

RunRecord failed_record() {
    RunRecord r;
    r.run_id = 7;
    r.algorithm = "nlopt:algorithm=LN_BOBYQA";
    r.problem = "sphere:dim=2";
    r.ok = false;
    r.message = "nlopt: bounds are inconsistent";
    r.evaluations = 3;
    return r;
}

std::string all_lines(const RenderedLines& lines) {
    return lines.run_line + lines.curve_lines + lines.checkpoint_lines + lines.trajectory_lines +
           lines.improvement_lines + lines.timing_line;
}

TEST(RecordBytes, TheStoredRecordIsPinned) {
    const std::string full = encode_record(awkward_record(), 12.75);
    EXPECT_EQ(full.size(), 652u);
    EXPECT_EQ(crc32c_hex(crc32c(full)), "edda7ce5");
    const std::string failed = encode_record(failed_record(), -0.0);
    EXPECT_EQ(failed.size(), 251u);
    EXPECT_EQ(crc32c_hex(crc32c(failed)), "361781d4");
}

TEST(RecordBytes, TheRenderedLinesArePinned) {
    const std::vector<std::string> columns = {"Lq", "psi", "Rs", "Ld"};
    EXPECT_EQ(all_lines(rendered_headers(columns)),
              "run_id,algorithm,problem,budget,run,seed,status,evaluations,iterations,best_f,f_opt,error,"
              "evals_to_target,best_x,Lq,Lq_true,Lq_opt,Lq_err_pct,psi,psi_true,psi_opt,psi_err_pct,Rs,"
              "Rs_true,Rs_opt,Rs_err_pct,Ld,Ld_true,Ld_opt,Ld_err_pct,message\n"
              "run_id,iteration,evaluations,best_f\n"
              "run_id,evaluations,best_f\n"
              "run_id,iteration,Lq,psi,Rs,Ld\n"
              "run_id,event,evaluations,f\n"
              "run_id,wall_seconds\n");
    EXPECT_EQ(all_lines(render_run(awkward_record(), 0.25, columns)),
              "123456789012,\"itlbo:label=\"\"a, b\"\"\",\"pmsm:load=2,speed=2500\",\"iterations=150,"
              "evaluations=20000,target=1e-08\",19,18364758544493064720,ok,15050,150,0.43333333333333335,"
              "5e-324,0.43333333333333335,0,0.36 inf -0 0.3333333333333333,,,,,-0,0.0776,-0,-100,0.36,0.365,"
              "0.365,-1.3698630136986314,inf,0,0.00325,,\"kept, though \"\"ok\"\" with a newline\"\n"
              "123456789012,0,50,2\n"
              "123456789012,1,100,1\n"
              "123456789012,2,150,-inf\n"
              "123456789012,1,9\n"
              "123456789012,100,nan\n"
              "123456789012,0,,0.07,0.3,0.002\n"
              "123456789012,2,,0.08,0.36,0.003\n"
              "123456789012,improvement,1,9\n"
              "123456789012,improvement,40,2\n"
              "123456789012,last,15050,0.5\n"
              "123456789012,0.25\n");
    EXPECT_EQ(all_lines(render_run(failed_record(), 1.5, columns)),
              "7,nlopt:algorithm=LN_BOBYQA,sphere:dim=2,,0,0,failed,3,0,,,,,,,,,,,,,,,,,,,,,,"
              "nlopt: bounds are inconsistent\n"
              "7,1.5\n");
    EXPECT_EQ(all_lines(rendered_headers({})),
              "run_id,algorithm,problem,budget,run,seed,status,evaluations,iterations,best_f,f_opt,error,"
              "evals_to_target,best_x,message\n"
              "run_id,iteration,evaluations,best_f\n"
              "run_id,evaluations,best_f\n"
              "run_id,iteration\n"
              "run_id,event,evaluations,f\n"
              "run_id,wall_seconds\n");
    EXPECT_EQ(all_lines(render_run(failed_record(), 1.5, {})),
              "7,nlopt:algorithm=LN_BOBYQA,sphere:dim=2,,0,0,failed,3,0,,,,,,nlopt: bounds are inconsistent\n"
              "7,1.5\n");
}

} // namespace
} // namespace mhb
