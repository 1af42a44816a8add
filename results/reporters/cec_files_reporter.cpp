// cec: the CEC organisers' result files in <budget>/cec when the study follows a CEC protocol
// (results/exports/cec_result_files.hpp). They are the competition's own tables of the runs'
// errors, so they are written with the report's tables, before the report says where those went.
#include "results/exports/cec_result_files.hpp"
#include "results/reporters/count_of.hpp"
#include "results/reporters/reporter.hpp"

namespace mhb {

namespace {

class CecFiles final : public Reporter {
public:
    std::string_view name() const override { return "cec"; }
    std::string_view description() const override {
        return "the CEC organisers' result files in cec/, when the study follows a CEC protocol";
    }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    // Without a protocol, the files of an earlier report of the study, when it followed one, are
    // removed: they would mislead.
    void write_tables(const BudgetReportContext& budget) const override {
        const std::filesystem::path& dir = budget.directory;
        std::ostream& console = budget.console;
        if (const CecProtocol* protocol = budget.protocol; protocol != nullptr) {
            const CecFilesSummary cec = write_cec_result_files(budget.index, *protocol, dir / "cec");
            console << protocol->title << " result files (" << cec.files
                    << ", the organisers' layout; see README there): " << (dir / "cec").string() << '\n';
            if (cec.failed_runs > 0)
                console << protocol->title << " result files: " << count_of(cec.failed_runs, "failed run")
                        << " left out\n";
        } else if (std::filesystem::exists(dir / "cec" / "README")) {
            std::error_code ec;
            std::filesystem::remove_all(dir / "cec", ec);
        }
    }
};

} // namespace

std::unique_ptr<Reporter> cec_files_reporter() {
    return std::make_unique<CecFiles>();
}

} // namespace mhb
