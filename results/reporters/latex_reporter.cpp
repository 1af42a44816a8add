// tex: each table as <id>.tex, the method text of their notes once in methods.tex, and report.tex,
// one LaTeX document with every table of every budget (results/latex/latex_document.hpp).
#include "results/latex/latex_document.hpp"
#include "results/latex/latex_table.hpp"
#include "results/reporters/reporter.hpp"
#include "results/store/csv.hpp"

namespace mhb {

namespace {

class LatexTables final : public TableFormatReporter {
public:
    std::string_view name() const override { return "tex"; }
    std::string_view description() const override {
        return "LaTeX, laid out to fit a journal's page: each table as <id>.tex, every table in report.tex";
    }
    bool selected_by_default() const override { return true; }
    std::string render(const Table& table) const override { return render_latex(table); }

    // methods.tex: the method text the tables' short notes leave out, once for the budget's tables.
    void write_budget(const BudgetReportContext& budget) const override {
        const std::string methods = latex_methods(budget.tables);
        std::error_code ec;
        if (methods.empty())
            std::filesystem::remove(budget.directory / "methods.tex", ec);
        else
            write_file_atomically(budget.directory / "methods.tex", methods);
    }

    std::optional<std::filesystem::path> write_study(const StudyReportContext& study) const override {
        std::vector<LatexSection> sections; // a section per budget when there are several
        for (const BudgetSection& budget : study.budgets) {
            LatexSection& section = sections.emplace_back();
            section.tables = budget.tables;
            if (budget.folder.empty())
                continue;
            section.heading =
                "Budget " + (budget.budget.empty() ? std::string("unspecified") : budget.budget);
            for (Table& table : section.tables)
                table.id = budget.folder + "_" + table.id; // one LaTeX label per table in report.tex
        }
        write_file_atomically(
            study.directory / "report.tex",
            latex_document(study.study.directory.string(), study.study.context_text, sections));
        return std::nullopt;
    }
};

} // namespace

std::unique_ptr<Reporter> latex_tables_reporter() {
    return std::make_unique<LatexTables>();
}

} // namespace mhb
