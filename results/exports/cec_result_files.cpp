#include "results/exports/cec_result_files.hpp"

#include <map>
#include <set>
#include <stdexcept>

#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace fs = std::filesystem;

namespace mhb {
namespace {

// A label as a file-name part: letters, digits, '.', '+' and '-' kept, every run of other characters
// one '-', none at either end ("CMA-ES (IPOP)" -> "CMA-ES-IPOP").
std::string safe_name(const std::string& label) {
    std::string out;
    for (const char c : label) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                          c == '.' || c == '+' || c == '-';
        if (keep)
            out += c;
        else if (!out.empty() && out.back() != '-')
            out += '-';
    }
    while (!out.empty() && out.back() == '-')
        out.pop_back();
    return out.empty() ? std::string("algorithm") : out;
}

std::string file_name(const std::string& algorithm, int function, std::int64_t dimension) {
    return algorithm + "_" + std::to_string(function) + "_" + std::to_string(dimension) + ".txt";
}

// Each algorithm's name in file names, in study order; two labels that become the same name get
// "-2", "-3", ... after the second and later.
std::map<std::string, std::string> file_algorithm_names(const StudyIndex& index) {
    std::map<std::string, std::string> names;
    std::set<std::string> taken;
    for (const auto& a : index.algorithms()) {
        const std::string base = safe_name(index.label(a));
        std::string name = base;
        for (int i = 2; taken.count(name) != 0; ++i)
            name = base + "-" + std::to_string(i);
        taken.insert(name);
        names[a] = name;
    }
    return names;
}

std::string readme(const StudyIndex& index, const CecProtocol& protocol,
                   const std::vector<CecProblem>& problems, const std::map<std::string, std::string>& names,
                   std::size_t failed) {
    std::string out = std::string(protocol.title) +
                      " result files, in the layout the organisers ask for (mhbench report).\n\n"
                      "<Algorithm>_<F>_<D>.txt: algorithm, function number F, dimension D. A row per "
                      "checkpoint, a column per run (run index 0, 1, ... left to right";
    out += failed > 0 ? "; " + std::to_string(failed) + " failed runs are left out" : std::string();
    out += ").\nEach value is the error f - f* of the best-so-far f after that many evaluations; an error "
           "below 1e-8 is written 0.\n";
    if (protocol.termination_row)
        out += "The last row is FEterm: the evaluation at which the error first fell below 1e-8, MaxFES "
               "for a run that never got there.\n";
    out +=
        "Budget: " + (index.budget().empty() ? std::string("unspecified") : index.budget()) + "\n\nRows:\n";
    const std::vector<std::string> rows = protocol.row_names();
    for (std::size_t i = 0; i < rows.size(); ++i)
        out += "  " + std::to_string(i + 1) + ". " + rows[i] + "\n";
    out += "\nEvaluation counts of the checkpoints per dimension:\n";
    std::int64_t last_dimension = -1;
    for (const auto& p : problems) {
        if (p.dimension == last_dimension)
            continue;
        last_dimension = p.dimension;
        out += "  D = ";
        out +=
            std::to_string(p.dimension) + ", MaxFES = " + std::to_string(p.max_fes) +
            (p.max_fes_from_budget ? "" : " (the most any run spent: the budget gives no evaluation count)") +
            ":";
        for (const std::int64_t c : protocol.checkpoints(p.max_fes, p.dimension))
            out.append(" ").append(std::to_string(c));
        out += "\n";
    }
    out += "\nAlgorithms (file name, label, spec):\n";
    for (const auto& a : index.algorithms())
        out += "  " + names.at(a) + "  " + index.label(a) + "  " + index.full_spec(a) + "\n";
    return out;
}

} // namespace

std::string cec_result_matrix(const CecProtocol& protocol, const std::vector<const RunRecord*>& runs,
                              std::int64_t max_fes, std::int64_t dimension) {
    std::string out;
    for (const std::int64_t checkpoint : protocol.checkpoints(max_fes, dimension)) {
        for (std::size_t r = 0; r < runs.size(); ++r)
            out.append(r == 0 ? "" : " ").append(csv_number(cec_error_at(*runs[r], checkpoint)));
        out += '\n';
    }
    if (protocol.termination_row) {
        for (std::size_t r = 0; r < runs.size(); ++r)
            out.append(r == 0 ? "" : " ")
                .append(std::to_string(cec_termination_evaluations(*runs[r], max_fes)));
        out += '\n';
    }
    return out;
}

std::string cec_file_name(const std::string& label, int function, std::int64_t dimension) {
    return file_name(safe_name(label), function, dimension);
}

CecFilesSummary write_cec_result_files(const StudyIndex& index, const CecProtocol& protocol,
                                       const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": cannot create the folder of the CEC result files");
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".txt")
            fs::remove(entry.path(), ec);

    const std::vector<CecProblem> problems = cec_problems(index, protocol);
    const auto names = file_algorithm_names(index);
    CecFilesSummary summary;
    for (const auto& p : problems)
        for (const auto& a : index.algorithms()) {
            const RunGroup* group = index.group(p.problem, a);
            if (group == nullptr)
                continue;
            summary.failed_runs += group->failed;
            if (group->runs.empty())
                continue;
            write_file_atomically(dir / file_name(names.at(a), p.function, p.dimension),
                                  cec_result_matrix(protocol, group->runs, p.max_fes, p.dimension));
            ++summary.files;
        }
    write_file_atomically(dir / "README", readme(index, protocol, problems, names, summary.failed_runs));
    return summary;
}

} // namespace mhb
