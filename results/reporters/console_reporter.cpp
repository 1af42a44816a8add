// console: the verdict of each budget (who won, verdict_lines.hpp) on the console, so that a report
// is read where it was made; with --tables every table in Markdown before it, whatever --format
// chose. The verdicts of all budgets share one screen: console_verdict_lines between them.
#include "results/reporters/reporter.hpp"
#include "results/reporters/verdict_lines.hpp"
#include "results/text/markdown_table.hpp"

namespace mhb {

namespace {

// The verdict lines of a whole report: the rest of a report's console (its counts, folders and
// the page) takes about 18 lines with two budgets, which then still fit 40.
constexpr std::size_t console_verdict_lines = 22;
// Fewer lines than these make no verdict a reader can use, however many budgets share the screen.
constexpr std::size_t least_verdict_lines = 8;

class ConsoleTables final : public Reporter {
public:
    std::string_view name() const override { return "console"; }
    std::string_view description() const override {
        return "the verdict of each budget on the console (--tables: every table in Markdown too)";
    }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    void write_tables(const BudgetReportContext& budget) const override {
        if (budget.console_tables)
            for (const Table& table : budget.tables)
                budget.console << render_markdown(table) << '\n';
        const std::size_t lines = std::max(
            least_verdict_lines, console_verdict_lines / std::max<std::size_t>(budget.budget_count, 1));
        for (const std::string& line : verdict_lines(budget.verdict, lines))
            budget.console << line << '\n';
    }
};

} // namespace

std::unique_ptr<Reporter> console_tables_reporter() {
    return std::make_unique<ConsoleTables>();
}

} // namespace mhb
