// Curve data for figures and for anyone who plots their own (one budget: a StudyIndex's): per
// (problem, algorithm; each row also carries the algorithm's display label) the best-so-far
// fitness over the runs (mean, std, median, quartiles) per iteration and on the shared
// evaluation-checkpoint grid; per named parameter the mean and std of the best-so-far value per
// iteration; the final values per run (for box plots); and the evaluation at which each run first
// reached each target gap (for fixed-target ECDFs). Each is a long-format CSV text; report/README.md
// (results/report/report_readme.hpp) is their data dictionary.
//
// One rule for every file: a run counts at every point, and a run that has stopped counts with
// its final value (best-so-far does not change after a run ends), so every point summarises all
// the group's successful runs.
//  - By iteration: iteration k is the end of iteration k, or the run's end if that came first. A
//    run that stopped inside iteration k (its budget or target reached there) counts with its
//    final value and evaluation count from iteration k on.
//  - By evaluations: the x-axis is the shared checkpoint grid (results/analysis/evaluation_counts.hpp); at
//    each count, each run's best-so-far after exactly that many evaluations, from its improvement
//    log, so a value is never that of an earlier grid point.
//  - Target hits: the evaluation that first reached the gap, from the improvement log.
// Runs stored before improvements were recorded have only sampled points (iteration ends and the
// grid): their values are those of the last sampled point, and their hits the first sampled point
// that reached the gap (late by up to one grid step).
#pragma once

#include <string>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// problem,algorithm,label,iteration,runs,evaluations_mean,mean,std,median,q25,q75
std::string fitness_curves_by_iteration(const StudyIndex& index);
// problem,algorithm,label,evaluations,runs,mean,std,median,q25,q75
std::string fitness_curves_by_evaluations(const StudyIndex& index);
// problem,algorithm,label,parameter,iteration,runs,mean,std,true,opt (only problems with named parameters)
std::string parameter_curves_by_iteration(const StudyIndex& index);
// problem,algorithm,label,run,best_f,evaluations,evals_to_target
std::string final_values(const StudyIndex& index);
// problem,name,f_opt: each problem's short name for titles (short_problem_names) and its known
// optimum (empty when unknown), so that figures draw the gap f - f* where f* is known.
std::string problem_facts(const StudyIndex& index);

// The gaps f - f* of the fixed-target ECDF, as COCO's bbob targets: 1e2, 1e1, ..., 1e-8.
const std::vector<double>& ecdf_target_gaps();
// problem,algorithm,label,run,target_gap,evaluations: the first evaluation at which best-so-far
// f - f* <= target_gap; empty when never reached. Only problems with a known optimum.
std::string target_hits(const StudyIndex& index);

} // namespace mhb
