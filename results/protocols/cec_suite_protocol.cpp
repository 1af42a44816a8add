// A CEC competition's rules as a protocol (results/analysis/cec_protocol.hpp has its numbers): the
// study's problems must be of the suite and its budgets give evaluation counts; the report adds the
// competition's tables per dimension (results/tables/cec_tables.hpp) and the organisers' result
// files in cec/ (results/exports/cec_result_files.hpp).
#include <memory>
#include <ostream>

#include "results/analysis/cec_protocol.hpp"
#include "results/exports/cec_result_files.hpp"
#include "results/protocols/suite_protocol.hpp"
#include "results/tables/cec_tables.hpp"

namespace mhb {
namespace {

class CecSuiteProtocol final : public SuiteProtocol {
public:
    explicit CecSuiteProtocol(const CecProtocol& rules)
        : rules_(rules), description_("the " + std::string(rules.title) +
                                      " competition's rules: its tables per dimension and the "
                                      "organisers' result files") {}

    [[nodiscard]] std::string_view name() const override { return rules_.name; }
    [[nodiscard]] std::string_view title() const override { return rules_.title; }
    [[nodiscard]] std::string_view description() const override { return description_; }

    // The protocol names its suite and records errors at fractions of the evaluation budget.
    void check_study(const ProtocolStudy& study, std::vector<std::string>& errors) const override {
        const std::string name(rules_.name);
        const std::string family(rules_.family);
        std::size_t others = 0;
        std::string first;
        for (const auto& problem : study.problems)
            if (problem.family != family && others++ == 0)
                first = problem.spec;
        if (others > 0)
            errors.push_back(
                "protocol " + name + ": " +
                (others > 1 ? "problems '" + first + "' and " + std::to_string(others - 1) + " more are"
                            : "problem '" + first + "' is") +
                " not of the " + family +
                " suite; the protocol's tables and result files cover its functions only (write " + family +
                ":f=...,dim=...)");
        for (const auto& budget : study.budgets)
            if (!budget.gives_evaluations)
                errors.push_back(
                    "protocol " + name + ": budget '" + budget.text +
                    "' gives no evaluation count; the protocol records errors at fractions of it "
                    "(write evaluations=" +
                    std::string(rules_.evaluations) + ")");
    }

    [[nodiscard]] std::string dry_run_line() const override {
        return "protocol: " + std::string(rules_.name) + " (" + std::string(rules_.title) +
               "): the report adds the competition's tables per dimension and the organisers' result files "
               "(report/" +
               std::string(files_folder()) + "/)";
    }

    [[nodiscard]] std::vector<Table> tables(const StudyIndex& index, const std::string& reference,
                                            double alpha) const override {
        return cec_tables(index, rules_, reference, alpha);
    }

    [[nodiscard]] std::string_view files_folder() const override { return "cec"; }

    void write_files(const StudyIndex& index, const std::filesystem::path& dir,
                     std::ostream& console) const override {
        const std::filesystem::path folder = dir / files_folder();
        const CecFilesSummary cec = write_cec_result_files(index, rules_, folder);
        console << rules_.title << " result files (" << cec.files
                << ", the organisers' layout; see README there): " << folder.string() << '\n';
        if (cec.failed_runs > 0)
            console << rules_.title << " result files: " << cec.failed_runs << " failed run"
                    << (cec.failed_runs == 1 ? "" : "s") << " left out\n";
    }

    // Only a folder the files were written to (its README says so): a folder of the user's stays.
    void remove_files(const std::filesystem::path& dir) const override {
        const std::filesystem::path folder = dir / files_folder();
        std::error_code ec;
        if (std::filesystem::exists(folder / "README", ec))
            std::filesystem::remove_all(folder, ec);
    }

private:
    const CecProtocol& rules_;
    std::string description_;
};

} // namespace

std::unique_ptr<SuiteProtocol> cec_suite_protocol(const CecProtocol& rules) {
    return std::make_unique<CecSuiteProtocol>(rules);
}

} // namespace mhb
