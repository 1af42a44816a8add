#include "results/html/html_figures.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "results/html/html_escape.hpp"
#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace mhb {

namespace fs = std::filesystem;

const std::vector<FigureKind>& figure_kinds() {
    static const std::vector<FigureKind> kinds = {
        {"convergence_iteration_", "Convergence by iteration",
         "Median best-so-far gap f - f* (f where f* is unknown, as the axis says) per iteration; the band "
         "is the interquartile range (order statistics, as meaningful on the log axis as on a linear "
         "one)."},
        {"convergence_evaluations_", "Convergence by evaluations",
         "Median best-so-far gap f - f* (f where f* is unknown) against evaluations (log-log); the band is "
         "the interquartile range."},
        {"parameters_", "Identified parameters",
         "Mean best-so-far parameter (band: one standard deviation) per iteration, or against the mean "
         "evaluations at an evaluation budget; dashed: the true value, dotted: the least-squares "
         "optimum."},
        {"final_values_", "Final values",
         "Box plots of the final gap f - f* (or f) of each algorithm's runs."},
        {"ecdf_targets_", "Fixed-target ECDFs",
         "Fraction of (run, target) pairs reached within a number of evaluations, over COCO's targets "
         "f - f* = 1e2 ... 1e-8."},
        {"ecdf_target_", "Runs that reached the study's target",
         "Fraction of runs that reached the study's target within a number of evaluations."},
        {"relative_gaps", "Relative gap to f* per problem",
         "Median relative gap (f - f*) / |f*| of the final values per problem (log axis, problems in the "
         "study's order), one line per algorithm: where the lines part, the optimisers stop being "
         "interchangeable."},
        {"critical_difference", "Critical difference",
         "Friedman average ranks across problems with the Nemenyi critical difference (Demsar 2006); a bar "
         "joins algorithms that do not differ significantly."},
        {"bayesian_simplex_", "Bayesian signed-rank tests",
         "Posterior samples of theta (the masses of reference better, equivalent within the ROPE, algorithm "
         "better) in the simplex, a panel per algorithm against the reference (Benavoli et al. 2017); the "
         "dashed lines part the regions where each mass is the largest, the vertices give its probability."},
        {"overhead", "Time per evaluation",
         "Median wall time per evaluation against the dimension (log-log), one line per algorithm: COCO's "
         "timing experiment (mhbench run --study timing); machine-dependent."},
        {"effects_overview_", "Effects of the components: overview",
         "Every main effect and two-way interaction of a 2^k on/off design, per problem (mean over blocks; "
         "negative: lower f, the component helps; hatched: not significant after Holm)."},
        {"effects_main_", "Main effects", "Mean response with each switch off and on."},
        {"effects_interaction_", "Two-way interactions",
         "Mean response of one switch off and on, one line per level of another."},
        {"structural_bias_", "Structural bias on f0",
         "The final best points on f0 (a random value at every evaluation), per dimension: each column a "
         "histogram of one coordinate over the runs, coloured by its density relative to uniform (white: "
         "as uniform, red: more, blue: fewer), a panel per algorithm titled with its verdict. A red band "
         "at 0.5 is a pull to the centre, red rows at 0 and 1 a pull to the bounds."},
        {"", "Other figures", ""},
    };
    return kinds;
}

std::size_t figure_kind_of(const std::string& name) {
    const auto& kinds = figure_kinds();
    for (std::size_t k = 0; k < kinds.size(); ++k)
        if (name.rfind(kinds[k].prefix, 0) == 0)
            return k;
    return kinds.size() - 1;
}

bool key_figure(const std::string& name) {
    for (const char* prefix : {"convergence_iteration_", "convergence_evaluations_", "final_values_"})
        if (name.rfind(prefix, 0) == 0)
            return true;
    return false;
}

std::vector<std::string> png_figures(const fs::path& directory) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(directory / "figures", ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (file.size() > 4 && file[0] != '.' && file.compare(file.size() - 4, 4, ".png") == 0 &&
            it->is_regular_file(ec))
            names.push_back(file.substr(0, file.size() - 4));
    }
    std::sort(names.begin(), names.end());
    return names;
}

namespace {

// "#1f77b4", "#abc" or a colour's name ("tab:blue" is not CSS: left out).
bool plain_css_colour(const std::string& colour) {
    if (colour.empty() || colour.size() > 32)
        return false;
    if (colour[0] == '#')
        return (colour.size() == 4 || colour.size() == 7 || colour.size() == 9) &&
               std::all_of(colour.begin() + 1, colour.end(),
                           [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; });
    return std::all_of(colour.begin(), colour.end(),
                       [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; });
}

} // namespace

std::map<std::string, std::string> figure_colours(const fs::path& directory) {
    std::map<std::string, std::string> colours;
    std::error_code ec;
    const fs::path file = directory / "figures" / "styles.csv";
    if (!fs::is_regular_file(file, ec))
        return colours;
    try {
        const CsvTable styles = read_csv(file);
        if (!styles.has_column("label") || !styles.has_column("colour"))
            return colours;
        const std::size_t label = styles.column("label");
        const std::size_t colour = styles.column("colour");
        for (const auto& row : styles.rows)
            if (plain_css_colour(row[colour]))
                colours[row[label]] = row[colour];
    } catch (const std::exception&) {
        colours.clear(); // a damaged styles.csv costs the colours, never the page
    }
    return colours;
}

std::string figure_html(const std::string& folder, const std::string& name, const std::string& anchor) {
    const std::string stem = html_escape((folder.empty() ? "" : folder + "/") + "figures/" + name);
    return "<figure id=\"" + html_escape(anchor) + "\">\n<a href=\"" + stem + ".pdf\"><img src=\"" + stem +
           ".png\" loading=\"lazy\" alt=\"" + html_escape(name) + "\"></a>\n<figcaption><code>figures/" +
           html_escape(name) + ".png</code> (<a href=\"" + stem + ".pdf\">PDF</a>)</figcaption>\n</figure>\n";
}

} // namespace mhb
