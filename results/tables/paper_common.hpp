// What the paper's tables (paper_tables.cpp: Tables 2 and 4; paper_parameter_table.cpp: Table 3)
// share: the PMSM problems of a study with the paper's condition each matches, the paper's entries
// for an algorithm, how the paper printed its numbers, and the caption phrases that cite it.
// Internal to results/tables/.
#pragma once

#include <string>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills
#include "results/tables/published_pmsm.hpp"

namespace mhb::tables {

inline constexpr const char* paper_citation = "Li, Wang, Ji (2017), J. System Simulation 29(2):393-401";

// The budget the paper ran (section 4: NP = 50 for 150 iterations), as StudyIndex::budget() writes
// it: only there are its tables framed as the paper's.
inline constexpr const char* paper_budget = "iterations=150";

// Where the paper's numbers appear, and what they were measured with.
inline constexpr const char* paper_rows_note =
    "; shown only beside itlbo, tlbo and pso with every parameter at its default (the paper's settings), "
    "never beside a variant; the paper ran NP = 50 for 150 iterations, 20 runs";

// A PMSM problem of the study as its tables name it. `published` is set only when the tables are
// framed as the paper's (the pmsm-paper protocol at the paper's budget) and the paper ran its
// condition: then its tables are the paper's Tables 2-3, beside the published values; otherwise
// they are the study's own fitness and parameters tables, with no paper column.
struct PmsmProblem {
    std::string spec;
    std::string name;                              // for titles: "PMSM, 2500 rpm, 2 N m" (pmsm_problem_name)
    const PublishedCondition* published = nullptr; // nullptr: neutral tables
    std::string suffix;                            // of the file names: "" for the first of its kind
};

// A PMSM problem's spec as a title names it, with no spec syntax: its condition ("PMSM, 2500 rpm,
// 2 N m"), the model and motor when they are not the paper's, "noisy" with measurement noise, and
// for logged data the files ("PMSM, logged data run1.csv").
std::string pmsm_problem_name(const std::string& spec);

// The paper's entries for this algorithm on this problem, if any: only for the configurations the
// paper ran, i.e. the canonical spec exactly "itlbo", "tlbo" or "pso" (every parameter at its
// default, which are the paper's settings). A variant (itlbo:obl=off, pso:w=0.7, a grid point) gets
// none, whatever its name.
const PublishedFitness* published_fitness(const PmsmProblem& p, const std::string& algorithm);
const PublishedIdentification* published_identification(const PmsmProblem& p, const std::string& algorithm);

// Index of parameter `name` in the paper's order, or -1.
int paper_parameter(const std::string& name);
// A PMSM parameter as the paper writes it: Rs -> $R_s$, psi -> $\psi_f$ (flux linkage).
std::string parameter_latex(const std::string& name);

// Digits after the point of a published value as the paper prints it (its shortest decimal form):
// a column of published values shows them with the most any of them has, which is exact for every
// one and adds no digit the paper did not print.
int printed_decimals(double value);

// "20 runs per algorithm", or "18-20 runs per algorithm" when the algorithms differ.
std::string runs_note(const StudyIndex& index, const std::string& problem);
// The paper, and its table for this problem's condition when it ran it.
std::string paper_source(const PmsmProblem& p);

// Table 3 "Parameter identification results" for one problem whose runs identify parameters.
Table parameter_table(const StudyIndex& index, const PmsmProblem& p);

} // namespace mhb::tables
