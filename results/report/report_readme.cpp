#include "results/report/report_readme.hpp"

#include <algorithm>

namespace mhb {

namespace {

// Conventions every file shares.
const char* const conventions = R"(## Conventions

- `problem` and `algorithm` are canonical specs (`name:key=value,...`, defaults dropped), as in
  `runs.csv`; `label` is the algorithm's display name from `algorithms.csv` (the spec when the study
  has none). `run` is the 0-based run index: runs with the same index share a seed when the study
  uses common random numbers.
- f is the problem's objective value as the problem computes it (for pmsm: the fitness of the
  identification, a weighted sum of squared residuals of the model); f* is its known minimum and
  f - f* the error, where the problem has one.
- Numbers are written at full precision (the shortest decimal that reads back as the same double);
  `inf` and `-inf` are written as such (a mean over both +inf and -inf has no value: NaN). Statistics
  over runs: mean, std = sample standard deviation (n - 1; 0 for one run), median and quartiles
  q25, q75 by linear interpolation (R's type 7); +inf is the largest value.
- Every run counts at every point: a run that has stopped counts with its final value (its
  best-so-far does not change after it ends). Failed runs are left out of everything (the tables'
  captions count them).
- Exact values come from each run's improvement log (`improvements.csv` of the study: every strict
  improvement of best-so-far f at the evaluation that made it). Runs stored before mhbench recorded
  improvements have only sampled points (iteration ends and the checkpoint grid): for them a value
  at a count is that of the last sampled point at or before it, and a hit is the first sampled
  point that reached the target (late by up to one grid step). `mhbench run ... --overwrite`
  computes them again exactly.

)";

const char* const curve_files = R"(## Curve data

### curves_iteration.csv

Convergence by iteration, one row per (problem, algorithm, iteration).

| column | meaning |
| --- | --- |
| problem, algorithm, label | the group (above) |
| iteration | 0 = after the initial population, k = after iteration k |
| runs | successful runs counted (every run of the group) |
| evaluations_mean | mean over the runs of the evaluation count at this point |
| mean, std, median, q25, q75 | of the runs' best-so-far f at this point |

Iteration k of a run is the end of iteration k, or the run's end if that came first. A run that
stopped inside iteration k (its budget or its target reached there) counts from iteration k on with
its final f and final evaluation count. Rows go up to the last iteration any run of the group
reached, completed or not.

### curves_evaluations.csv

Convergence by evaluations, one row per (problem, algorithm, evaluation count).

| column | meaning |
| --- | --- |
| problem, algorithm, label | the group |
| evaluations | an evaluation count of the x-axis |
| runs | successful runs counted (every run of the group) |
| mean, std, median, q25, q75 | of the runs' best-so-far f after exactly that many evaluations |

The x-axis is the checkpoint grid every run shares, about ten points a decade (round(10^(k/10)) for
k = 0, 1, 2, ...: 1, 2, 3, 4, 5, 6, 8, 10, 13, 16, 20, 25, ...), up to the largest count a run of the
group spent, and each run's own final count. At each count every run contributes its best-so-far
after exactly that many evaluations, from its improvement log (its final value once it has stopped).

### parameters_iteration.csv

The identified parameters by iteration (problems with named parameters only, e.g. pmsm), one row per
(problem, algorithm, parameter, iteration).

| column | meaning |
| --- | --- |
| problem, algorithm, label | the group |
| parameter | its name (pmsm: Rs in ohm, Ld and Lq in H, psi in Wb, Vdt in V) |
| iteration | as in curves_iteration.csv |
| runs | runs counted (every run of the group) |
| mean, std | over the runs of the parameter's value at the best-so-far point |
| true | the value that generated the data (simulated drives); empty when unknown |
| opt | the value at the problem's known optimum (the exact least-squares fit); empty when unknown |

The same rule as curves_iteration.csv: a run that stopped counts with its final best point.

### final_values.csv

One row per successful run.

| column | meaning |
| --- | --- |
| problem, algorithm, label, run | the run |
| best_f | its final best-so-far f |
| evaluations | the evaluations it spent |
| evals_to_target | the evaluation at which it reached the study's target (f - f* <= target, or f - f* <= relative_target x abs(f*) for a relative target); empty without a target or when not reached |

### problems.csv

One row per problem, in the study's order: what the figures need to title a problem and to draw
the gap f - f* where the optimum is known.

| column | meaning |
| --- | --- |
| problem | the problem's spec |
| name | a short name: the family and the parameters that differ between the study's problems |
| f_opt | its known optimum f*; empty when unknown |

)";

const char* const target_hits_file = R"(### target_hits.csv

The data of fixed-target ECDFs: one row per (run, target gap), for problems with a known f*.

| column | meaning |
| --- | --- |
| problem, algorithm, label, run | the run |
| target_gap | a target f - f* <= gap, COCO's bbob targets 1e2, 1e1, ..., 1e-8 |
| evaluations | the evaluation that first reached it (best-so-far f - f* <= gap), exact from the improvement log; empty when the run never reached it |

The ECDF figures count, per algorithm, the (run, gap) pairs reached within each evaluation count.

)";

const char* const critical_difference_file = R"(### critical_difference.csv

The data of the critical-difference diagram (Demsar 2006): algorithms ranked on each problem by the
median of their final values (rank 1 the best, ties share the mean rank), ranks averaged over the
problems every algorithm completed.

| column | meaning |
| --- | --- |
| algorithm, label | the algorithm |
| average_rank | its average Friedman rank |
| cd | the Nemenyi critical difference q_alpha sqrt(k (k + 1) / (6 N)): two average ranks further apart differ significantly |
| alpha | the significance level (0.05 or 0.10: Demsar's Table 5) |
| problems | N, the problems ranked |

)";

const char* const effect_means_file = R"(### effect_means.csv

The points of the main-effects and interaction plots of a factorial design (the `effects` table).

| column | meaning |
| --- | --- |
| design | the design: the algorithm and its on/off switches (`itlbo: tutorial x stepwise x obl (2^3)`) |
| problem | a problem, or `all problems (N)` for the analysis pooled over N problems |
| scale | `log10(f - f*)` (a run's response: log10 of max(f - f*, floor), floor = max(1e-300, 4 eps abs(f*))) or `within-block rank` (the rank of f among the variants of its block) |
| blocks | (problem, run index) blocks with a successful run of every variant |
| factor, level | a switch and its value (on/off) |
| factor2, level2 | a second switch and its value for an interaction point; empty for a main effect |
| mean_response | the mean response over the blocks at those levels |

)";

const char* const relative_gaps_file = R"(### relative_gap_medians.csv

The data of the `relative_gaps` table and figure (a budget with a relative target, two or more
problems with a known, non-zero f*): one row per (problem, algorithm), problems in the study's order.

| column | meaning |
| --- | --- |
| problem, algorithm, label | the group |
| name | the problem's short name in the table's headers and on the figure's axis: its family and the parameters that tell it from the study's other problems of that family |
| f_opt | the problem's f* |
| runs, failed | successful and failed runs |
| median_relative_gap | median over the successful runs of (f - f*) / abs(f*), f the run's final best value; 0 or below: f* reached to the precision of doubles, or a best-known f* bettered; empty without a successful run |
| reached | runs that reached the study's target |
| success_rate | reached / (runs + failed) |

)";

const char* const final_points_file = R"(### final_points.csv

The final best points of the runs on f0 (the structural-bias audit, the `structural_bias` table
and figure): one row per coordinate of each successful run's best point.

| column | meaning |
| --- | --- |
| problem | the f0 problem (`f0:dim=30`) |
| algorithm | the algorithm's label |
| run | the run index |
| dimension | the coordinate, from 1 |
| x | its value in [0, 1] (best_x of runs.csv, every digit) |

### uniformity_tests.csv

The structural-bias audit's tests, one row per problem, algorithm and dimension: the final points'
coordinate in that dimension against U(0, 1), over the `runs` successful runs.

| column | meaning |
| --- | --- |
| problem, algorithm | the f0 problem and the algorithm's label |
| runs | the final points tested |
| dimension | the coordinate, from 1 |
| ks_statistic, ks_p | Kolmogorov-Smirnov D and its exact two-sided p-value (as scipy.stats.kstest(x, "uniform")) |
| ks_holm_p | ks_p Holm-adjusted across the dimensions |
| ad_statistic, ad_p | Anderson-Darling A^2 against U(0, 1) and its p-value (Marsaglia and Marsaglia 2004) |
| ad_holm_p | ad_p Holm-adjusted across the dimensions |

)";

const char* const bayesian_files = R"(### bayesian_probabilities.csv, bayesian_samples.csv

The Bayesian signed-rank tests of the `bayesian` table (Benavoli, Corani, Demsar, Zaffalon, JMLR
18, 2017): a row per test of an algorithm against the reference, per problem on the paired runs
and, with two or more problems that all know f*, across problems on per-problem medians. The
differences are reference - algorithm of the compared value, so "reference better" is the region
left of -rope. Prior: strength 0.5 at 0; 50 000 Monte Carlo samples, seeded by the test's names.

| column | meaning |
| --- | --- |
| problem | a problem, or `all problems (N)` for the test on the medians of N problems |
| algorithm, reference | labels |
| across_problems | 1 for the test on per-problem medians, else 0 |
| scale | `log10_gap`: log10(max(f - f*, floor)), floor = max(1e-300, 4 eps abs(f*)); `f`: the final f (f* unknown) |
| rope | the ROPE's half-width in the scale's units (decades for log10_gap); empty: no ROPE (raw f without --raw-rope) |
| pairs | the paired differences (runs, or problems) |
| p_reference_better, p_equivalent, p_algorithm_better | the share of the Monte Carlo samples of theta in which that region's posterior mass is the largest (ties shared); they sum to 1 |
| theta_reference_better, theta_equivalent, theta_algorithm_better | the posterior means of the three masses |

`bayesian_samples.csv` (problem, algorithm, sample, theta_reference_better, theta_equivalent,
theta_algorithm_better): the first 300 Monte Carlo samples of theta of the across-problems tests
(of every per-problem test when there are none), the points of the simplex figures.

)";

const char* const other_files = R"(## Other files

- `ioh/`: the IOHprofiler export for IOHanalyzer, as IOHexperimenter's analyzer logger writes it
  (a .json per function and a .dat per function and dimension; a row per improvement). raw_y is
  written `%.10f` by default, the logger's own format: every error below 5e-11 reads 0 and only ten
  decimals of smaller errors survive. `mhbench report DIR --ioh-precision full` writes every digit
  instead (IOHanalyzer reads both); the full-precision values are also in the study's
  `improvements.csv`.
)";

// Unlike join() (table_model/table.hpp), an empty item keeps its separator: a column header may be
// empty, and the list must still show where it stands.
std::string join_every(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i == 0 ? "" : separator) + items[i];
    return out;
}

// A table cell of Markdown: no '|' or line break breaks the row.
std::string cell(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::string out;
    for (const char c : text)
        out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string tables_section(const std::vector<Table>& tables, const std::vector<std::string>& formats) {
    if (tables.empty() || formats.empty())
        return "";
    std::string out =
        "## Tables\n\nEach table is written as `<id>." + join_every(formats, "`, `<id>.") +
        "`. The CSV holds every value at full precision; a cell that shows two numbers "
        "(\"median (IQR) marker\") keeps that text. The w/t/l rows under a table are in Markdown "
        "and LaTeX only. What each column means is in the caption.\n\n"
        "| file | title | columns | caption |\n| --- | --- | --- | --- |\n";
    for (const auto& t : tables)
        out += "| " + cell(t.id) + " | " + cell(t.title) + " | " + cell(join_every(t.header, "; ")) + " | " +
               cell(t.caption) + " |\n";
    return out + '\n';
}

} // namespace

std::string report_readme(const std::vector<Table>& tables, const ReportFiles& files) {
    std::string out = "# The files of this report\n\nWritten by `mhbench report` with the tables; every "
                      "file here is computed from the study directory alone.\n\n";
    out += conventions;
    out += tables_section(tables, files.formats);
    out += curve_files;
    out += target_hits_file;
    if (files.critical_difference)
        out += critical_difference_file;
    if (files.effect_means)
        out += effect_means_file;
    if (files.relative_gaps)
        out += relative_gaps_file;
    if (files.final_points)
        out += final_points_file;
    if (files.bayesian)
        out += bayesian_files;
    out += other_files;
    if (files.cec)
        out += "- `cec/`: the CEC organisers' result files, a row per checkpoint and a column per run; its "
               "README names every checkpoint's evaluation count.\n";
    if (files.figures)
        out += "- `figures/`: every figure as PDF (vector, fonts embedded) and PNG, drawn by "
               "scripts/plot_study.py from the CSV files above; `figures/styles.csv` gives each "
               "algorithm's colour, marker and line style.\n";
    if (files.budget_txt)
        out += "- `budget.txt`: the budget every run of this report had.\n";
    if (files.combined)
        out +=
            "- `report.md`, `report.tex`: every table in one file; `index.html`: the verdict first, the key "
            "figures, every table and figure, the study's context last.\n";
    return out;
}

std::string budgets_readme(const std::vector<std::string>& budgets, const std::vector<std::string>& folders) {
    std::string out = "# The files of this report\n\nThe study ran under several budgets; each is a separate "
                      "experiment with a complete report in its own folder, whose README.md describes its "
                      "files.\n\n| budget | folder |\n| --- | --- |\n";
    for (std::size_t i = 0; i < budgets.size() && i < folders.size(); ++i)
        out += "| " + cell(budgets[i].empty() ? "unspecified" : budgets[i]) + " | `" + folders[i] + "/` |\n";
    out +=
        "\n- `budgets.csv` (budget,directory): the same list.\n"
        "- `report.md`, `report.tex`: every table of every budget, a section per budget; `index.html`: the "
        "verdict and key figures of every budget, linking a page per budget (`budget_<folder>.html`) with "
        "its "
        "tables and figures.\n";
    return out;
}

} // namespace mhb
