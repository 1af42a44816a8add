// The paper's Tables 2-4 (Li, Wang, Ji 2017; results/tables/paper_tables.hpp) as a protocol a study
// opts into (`protocol = pmsm-paper`: the presets paper, paper-table4 and paper-noisy). At the
// paper's budget (150 iterations) its tables stand instead of the study's own PMSM tables, framed
// and numbered as the paper's, beside the published values; at any other budget the study's own
// tables stay, with no paper column: the paper never ran it.
#include <algorithm>
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
        return "the paper's Tables 2-4 for the study's PMSM problems at its budget (iterations=150), beside "
               "the published values";
    }

    // Its tables need the paper's problem.
    void check_study(const ProtocolStudy& study, std::vector<std::string>& errors) const override {
        if (std::none_of(study.problems.begin(), study.problems.end(),
                         [](const ProtocolStudy::Problem& p) { return p.family == "pmsm"; }))
            errors.emplace_back("protocol pmsm-paper: the study has no pmsm problem (the paper's tables are "
                                "of PMSM identification)");
    }
    [[nodiscard]] std::string dry_run_line() const override {
        return "the paper's Tables 2-4 at budget iterations=150; the study's own PMSM tables at any other";
    }

    // The paper's results lead, before the statistics of every problem.
    [[nodiscard]] ProtocolTablesPlace tables_place() const override {
        return ProtocolTablesPlace::before_comparisons;
    }
    [[nodiscard]] bool replaces_pmsm_tables(const StudyIndex& index) const override {
        return is_paper_budget(index.budget());
    }
    [[nodiscard]] std::vector<Table> tables(const StudyIndex& index, const std::string& /*reference*/,
                                            double /*alpha*/) const override {
        return replaces_pmsm_tables(index) ? pmsm_paper_tables(index) : std::vector<Table>{};
    }
};

} // namespace

std::unique_ptr<SuiteProtocol> pmsm_paper_protocol() {
    return std::make_unique<PmsmPaperProtocol>();
}

} // namespace mhb
