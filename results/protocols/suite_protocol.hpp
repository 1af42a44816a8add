// A suite protocol: rules a study follows on top of running its problems, as one component that
// both the runner and the report ask (issue 36). The CEC 2017 and CEC 2022 competitions' rules and
// the paper's Tables 2-4 are protocols (builtin_protocols.cpp); protocol_registry.hpp finds them.
//
// The runner asks a protocol whether a study may follow it (its problems, its budgets) and what the
// dry run says of it; the report asks for its tables at each budget and for its files in each
// budget's report directory. A protocol changes no run: a study's runs are those of the same study
// without it.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

// What the runner tells a protocol of a study it prepares (the runner's own types stay above
// results/): each problem's canonical spec and family, each budget as written.
struct ProtocolStudy {
    struct Problem {
        std::string spec;   // canonical: "cec2017:dim=10,f=1"
        std::string family; // its spec's name: "cec2017"
    };
    struct Budget {
        std::string text;               // "evaluations=10000*dim,target=1e-08"
        bool gives_evaluations = false; // an evaluation count, fixed or by dimension
    };
    std::vector<Problem> problems;
    std::vector<Budget> budgets;
};

// Where a protocol's tables stand among a budget's tables.
enum class ProtocolTablesPlace {
    before_comparisons, // after the algorithms table, before the statistics: the paper's Tables 2-4
    after_comparisons,  // after the statistics and the relative gaps, before the effects: CEC's tables
};

class SuiteProtocol {
public:
    virtual ~SuiteProtocol() = default;

    [[nodiscard]] virtual std::string_view name() const = 0;        // as `protocol =` writes it: "cec2017"
    [[nodiscard]] virtual std::string_view title() const = 0;       // "CEC 2017"
    [[nodiscard]] virtual std::string_view description() const = 0; // one line: what following it gives
    // In force for every study, named or not (none of the built-ins is). Such a protocol cannot be
    // named by `protocol =`, nor is it listed where the names are; returning false makes it one a
    // study opts into by name.
    [[nodiscard]] virtual bool applies_unnamed() const { return false; }

    // The runner. Appends one line per reason the study cannot follow the protocol.
    virtual void check_study(const ProtocolStudy& /*study*/, std::vector<std::string>& /*errors*/) const {}
    // The dry run's line on what the report will add; "" for none.
    [[nodiscard]] virtual std::string dry_run_line() const { return {}; }

    // The report. Its tables at one budget (`reference`: an algorithm spec of the index; `alpha`:
    // the markers' significance level), placed as tables_place() says.
    [[nodiscard]] virtual ProtocolTablesPlace tables_place() const {
        return ProtocolTablesPlace::after_comparisons;
    }
    [[nodiscard]] virtual std::vector<Table>
    tables(const StudyIndex& /*index*/, const std::string& /*reference*/, double /*alpha*/) const {
        return {};
    }
    // Whether its tables at this budget stand instead of the PMSM tables every study with PMSM
    // problems gets (tables/paper_tables.hpp pmsm_tables): the paper's protocol frames the same
    // tables as the paper's Tables 2-4.
    [[nodiscard]] virtual bool replaces_pmsm_tables(const StudyIndex& /*index*/) const { return false; }
    // Its files: the folder of a budget's report directory that holds them ("cec"; "" when it
    // writes none). Protocols may share one: it is left alone while any protocol in force writes it.
    [[nodiscard]] virtual std::string_view files_folder() const { return {}; }
    // Writes its files into `dir`/files_folder() and says so on `console`. Throws
    // std::runtime_error when a file cannot be written.
    virtual void write_files(const StudyIndex& /*index*/, const std::filesystem::path& /*dir*/,
                             std::ostream& /*console*/) const {}
    // Removes what write_files wrote into `dir` for an earlier report: the study no longer follows
    // the protocol, and stale files would mislead.
    virtual void remove_files(const std::filesystem::path& /*dir*/) const {}
};

} // namespace mhb
