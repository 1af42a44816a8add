// The figures of a report folder as the HTML pages show them: figures/NAME.png as a lazily loaded
// <img> linking to NAME.pdf beside it (no figure is inlined, so a page stays small whatever the
// study), grouped by kind (convergence, final values, ...), and the algorithms' colours of the
// figures (figures/styles.csv: algorithm,label,colour,marker,linestyle), which the pages' tables
// share. A folder without a .png shows no figure; a missing styles.csv means no colour.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mhb {

// A kind of figure of scripts/plot_study.py, by file-name prefix.
struct FigureKind {
    const char* prefix;
    const char* heading;
    const char* description;
};

// Every kind, in the order a reader wants them; the last (prefix "") takes the other figures.
const std::vector<FigureKind>& figure_kinds();
std::size_t figure_kind_of(const std::string& name);
// Whether the figure is one of a problem's key figures: its convergence and its final values.
bool key_figure(const std::string& name);

// The names (without .png) of `directory`/figures/*.png, sorted; temporary files (".name") left out.
std::vector<std::string> png_figures(const std::filesystem::path& directory);

// figures/styles.csv of `directory`: label -> colour ("#1f77b4"); empty when absent or unreadable,
// and a colour that is not a plain CSS colour (#hex or a name) is left out.
std::map<std::string, std::string> figure_colours(const std::filesystem::path& directory);

// One <figure>: the image `folder`/figures/NAME.png (folder "" for the page's own), a link to the
// PDF, and `anchor` as its id.
std::string figure_html(const std::string& folder, const std::string& name, const std::string& anchor);

} // namespace mhb
