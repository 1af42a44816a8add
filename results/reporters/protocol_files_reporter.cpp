// protocol-files: the files the study's protocols ask for in each budget's folder (the CEC
// organisers' result files in cec/; results/protocols/). They are the competition's own tables of
// the runs' errors, so they are written with the report's tables, before the report says where
// those went.
#include "results/protocols/protocol_report.hpp"
#include "results/reporters/reporter.hpp"

namespace mhb {

namespace {

class ProtocolFiles final : public Reporter {
public:
    std::string_view name() const override { return "protocol-files"; }
    std::string_view description() const override {
        return "the files the study's protocol asks for (the CEC organisers' result files in cec/)";
    }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    // Those of an earlier report for a protocol no longer in force are removed: they would mislead.
    void write_tables(const BudgetReportContext& budget) const override {
        write_protocol_files(budget.protocols, budget.index, budget.directory, budget.console);
    }
};

} // namespace

std::unique_ptr<Reporter> protocol_files_reporter() {
    return std::make_unique<ProtocolFiles>();
}

} // namespace mhb
