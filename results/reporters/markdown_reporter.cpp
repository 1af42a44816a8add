// md: each table as <id>.md, and report.md, every table of every budget in one file headed by the
// study's context (a table read later says what produced it).
#include "results/reporters/reporter.hpp"
#include "results/store/csv.hpp"
#include "results/text/markdown_table.hpp"

namespace mhb {

namespace {

class MarkdownTables final : public TableFormatReporter {
public:
    std::string_view name() const override { return "md"; }
    std::string_view description() const override {
        return "Markdown: each table as <id>.md, every table in report.md";
    }
    bool selected_by_default() const override { return true; }
    std::string render(const Table& table) const override { return render_markdown(table); }

    std::optional<std::filesystem::path> write_study(const StudyReportContext& study) const override {
        const std::string& context = study.study.context_text;
        std::string all = "# mhbench report: " + study.study.directory.string() +
                          "\n\nStudy context (context.ini):\n\n```\n" + context +
                          (context.empty() || context.back() == '\n' ? "" : "\n") + "```\n\n";
        for (const BudgetSection& section : study.budgets) {
            if (!section.folder.empty()) // several budgets: a section each
                all += "## Budget " + (section.budget.empty() ? std::string("unspecified") : section.budget) +
                       " (" + section.folder + "/)\n\n";
            for (const Table& table : section.tables)
                all += render_markdown(table) + '\n';
        }
        write_file_atomically(study.directory / "report.md", all);
        return std::nullopt;
    }
};

} // namespace

std::unique_ptr<Reporter> markdown_tables_reporter() {
    return std::make_unique<MarkdownTables>();
}

} // namespace mhb
