// Reporter: one output of a report (a table format, the HTML page, an export, the console's tables),
// in the manner of google/benchmark's reporters. build_report (results/report/) decides what a
// report holds and when; a reporter only turns what it is handed into files or console lines.
// Reporters are registered by name (reporter_registry.hpp), so a new format is one file and one
// registration line, and report.cpp never names a format.
//
// A report calls, for every reporter it uses, in registration order:
//   per budget  write_tables(budget)  as soon as the budget's tables are built
//               write_budget(budget)  after the tables and the curve data are written
//   once        write_study(study)    after every budget, into the report's top folder
// Each hook does nothing unless overridden. The console lines of a report keep their order only
// because the hooks run in this order: what a reporter says about tables goes in write_tables.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "results/analysis/verdict.hpp"
#include "results/exports/ioh_export.hpp"
#include "results/protocols/suite_protocol.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_index.hpp"
#include "results/table_model/table.hpp"

namespace mhb {

// What one budget's report hands each reporter.
struct BudgetReportContext {
    const StudyIndex& index;          // the budget's runs
    const std::vector<Table>& tables; // its tables, titled and captioned with the budget
    std::filesystem::path directory;  // its report folder (the report's top folder with one budget)
    const std::vector<const SuiteProtocol*>& protocols; // the protocols in force (protocol_registry.hpp)
    IohPrecision ioh_precision;                         // raw_y of the IOHprofiler export
    std::ostream& console;
    const BudgetVerdict& verdict; // who won: what the console says instead of every table
    bool console_tables = false;  // print every table on the console too (--tables)
    std::size_t budget_count = 1; // the report's budgets: their verdicts share one screen
};

// One budget's part of the documents that hold the whole report (report.md, index.html, ...).
struct BudgetSection {
    std::string budget;              // as recorded, e.g. "iterations=150"; empty: not recorded
    std::string folder;              // its folder under the report's top one; empty: the flat layout
    std::filesystem::path directory; // that folder on disk
    std::vector<Table> tables;
    // The verdict as tables (results/tables/verdict_tables.hpp): the page opens with it.
    std::vector<Table> verdict;
    // What a reader must know about the figures (skipped, failed, interrupted, not drawn);
    // empty when they were drawn without trouble.
    std::string figures_note;
    bool figures_current = true; // false: figures/ holds an earlier report's figures, if any
};

// What the end of a report hands each reporter.
struct StudyReportContext {
    const StudyData& study;
    std::filesystem::path directory; // the report's top folder
    const std::vector<BudgetSection>& budgets;
    std::ostream& console;
};

enum class ReporterKind {
    table_format, // writes every table as <id>.<name>; chosen with --format
    every_report, // written by every report: the HTML page, the exports, the console's tables
};

class Reporter {
public:
    virtual ~Reporter() = default;

    // Unique; a table format's is also its files' extension and what --format names.
    [[nodiscard]] virtual std::string_view name() const = 0;
    // One line for `mhbench list formats`.
    [[nodiscard]] virtual std::string_view description() const = 0;
    [[nodiscard]] virtual ReporterKind kind() const = 0;

    virtual void write_tables(const BudgetReportContext& /*budget*/) const {}
    virtual void write_budget(const BudgetReportContext& /*budget*/) const {}
    // Returns the page `mhbench report --open` shows, when this reporter wrote one.
    virtual std::optional<std::filesystem::path> write_study(const StudyReportContext& /*study*/) const {
        return std::nullopt;
    }
};

// A table format: the budget's tables each in a file <id>.<name()>, from render(). Override
// write_study too for a document holding every table of every budget (report.md, report.tex).
class TableFormatReporter : public Reporter {
public:
    [[nodiscard]] ReporterKind kind() const final { return ReporterKind::table_format; }
    // Whether a report without --format writes it.
    [[nodiscard]] virtual bool selected_by_default() const { return false; }
    // The text of <id>.<name()>.
    [[nodiscard]] virtual std::string render(const Table& table) const = 0;

    void write_tables(const BudgetReportContext& budget) const override;
};

} // namespace mhb
