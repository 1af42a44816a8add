// console: every table of a budget in Markdown on the console, whatever --format chose, so that a
// report is read where it was made.
#include "results/reporters/reporter.hpp"
#include "results/text/markdown_table.hpp"

namespace mhb {

namespace {

class ConsoleTables final : public Reporter {
public:
    std::string_view name() const override { return "console"; }
    std::string_view description() const override { return "every table in Markdown on the console"; }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    void write_tables(const BudgetReportContext& budget) const override {
        for (const Table& table : budget.tables)
            budget.console << render_markdown(table) << '\n';
    }
};

} // namespace

std::unique_ptr<Reporter> console_tables_reporter() {
    return std::make_unique<ConsoleTables>();
}

} // namespace mhb
