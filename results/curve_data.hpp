// Curve data for figures and for anyone who plots their own (one budget: a StudyIndex's): per
// (problem, algorithm; each row also carries the algorithm's display label) the
// best-so-far fitness over the runs (mean, std, median, quartiles) per iteration and on the shared
// evaluation-checkpoint grid; per named parameter the mean and std of the best-so-far value per
// iteration; and the final values per run (for box plots and ECDFs). Each is a long-format CSV
// text. A run that stopped earlier than others of its group keeps its last best-so-far value
// (best-so-far does not change after a run ends), so every point averages over all runs.
#pragma once

#include <string>

#include "results/study_index.hpp"

namespace mhb {

// problem,algorithm,label,iteration,runs,evaluations_mean,mean,std,median,q25,q75
std::string fitness_curves_by_iteration(const StudyIndex& index);
// problem,algorithm,label,evaluations,runs,mean,std,median,q25,q75
std::string fitness_curves_by_evaluations(const StudyIndex& index);
// problem,algorithm,label,parameter,iteration,runs,mean,std,true,opt (only problems with named parameters)
std::string parameter_curves_by_iteration(const StudyIndex& index);
// problem,algorithm,label,run,best_f,evaluations,evals_to_target
std::string final_values(const StudyIndex& index);

// The gaps f - f* of the fixed-target ECDF, as COCO's bbob targets: 1e2, 1e1, ..., 1e-8.
const std::vector<double>& ecdf_target_gaps();
// problem,algorithm,label,run,target_gap,evaluations: the first recorded evaluation count (iteration
// ends and checkpoints) at which best-so-far f - f* <= target_gap; empty when never reached. Only
// problems with a known optimum.
std::string target_hits(const StudyIndex& index);

} // namespace mhb
