// The paper's Tables 2-4 (Li, Wang, Ji 2017; results/tables/paper_tables.hpp) as a protocol. It is
// in force for every study: the tables appear whenever the study has the paper's PMSM problems, as
// they did before protocols were components, and not otherwise (the builder finds the problems).
// Making it one a study opts into (`protocol = pmsm-paper`) is applies_unnamed() returning false.
#include <memory>

#include "results/protocols/suite_protocol.hpp"
#include "results/tables/paper_tables.hpp"

namespace mhb {
namespace {

class PmsmPaperProtocol final : public SuiteProtocol {
public:
    [[nodiscard]] std::string_view name() const override { return "pmsm-paper"; }
    [[nodiscard]] std::string_view title() const override { return "the paper's Tables 2-4"; }
    [[nodiscard]] std::string_view description() const override {
        return "the paper's Tables 2-4 for the study's PMSM problems, beside the published values";
    }
    [[nodiscard]] bool applies_unnamed() const override { return true; }

    // The paper's results lead, before the statistics of every problem.
    [[nodiscard]] ProtocolTablesPlace tables_place() const override {
        return ProtocolTablesPlace::before_comparisons;
    }
    [[nodiscard]] std::vector<Table> tables(const StudyIndex& index, const std::string& /*reference*/,
                                            double /*alpha*/) const override {
        return pmsm_paper_tables(index);
    }
};

} // namespace

std::unique_ptr<SuiteProtocol> pmsm_paper_protocol() {
    return std::make_unique<PmsmPaperProtocol>();
}

} // namespace mhb
