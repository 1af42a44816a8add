// ioh: the runs in the IOHprofiler format in <budget>/ioh, for IOHanalyzer
// (results/exports/ioh_export.hpp), and what it left out said on the console.
#include "results/exports/ioh_export.hpp"
#include "results/reporters/count_of.hpp"
#include "results/reporters/reporter.hpp"

namespace mhb {

namespace {

class IohExport final : public Reporter {
public:
    std::string_view name() const override { return "ioh"; }
    std::string_view description() const override {
        return "the runs in the IOHprofiler format in ioh/, for IOHanalyzer (--ioh-precision)";
    }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    void write_budget(const BudgetReportContext& budget) const override {
        const std::filesystem::path dir = budget.directory / "ioh";
        say(write_ioh_export(budget.index, dir, budget.ioh_precision), dir, budget.console);
    }

private:
    static void say(const IohExportSummary& ioh, const std::filesystem::path& dir, std::ostream& console) {
        if (ioh.files > 0)
            console << "IOHprofiler export (" << ioh.files
                    << " files, load the folder in IOHanalyzer): " << dir.string() << '\n';
        else
            console << "IOHprofiler export: no run has a finite value to export\n";
        if (ioh.runs_left_out > 0)
            console << "IOHprofiler export: left out " << count_of(ioh.runs_left_out, "run")
                    << " that ended at +inf (no improvement to log, as IOHexperimenter would log none)\n";
        if (ioh.none_values > 0)
            console << "IOHprofiler export: " << count_of(ioh.none_values, "infinite value")
                    << " written None, as IOHexperimenter writes them\n";
        if (ioh.approximate_runs > 0)
            console
                << "IOHprofiler export: " << count_of(ioh.approximate_runs, "run")
                << " stored before mhbench recorded improvements: rows where the trace recorded them, not "
                   "at each improvement (approximate; run the study again with --overwrite for exact rows)\n";
    }
};

} // namespace

std::unique_ptr<Reporter> ioh_export_reporter() {
    return std::make_unique<IohExport>();
}

} // namespace mhb
