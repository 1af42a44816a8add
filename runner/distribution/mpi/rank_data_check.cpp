#include "runner/distribution/mpi/rank_data_check.hpp"

#include <mpi.h>
#include <sstream>

#include "runner/execution/context.hpp"
#include "runner/execution/data_provenance.hpp"

namespace mhb {
namespace {

// Every rank's text, concatenated on rank 0 (with each one's length); empty elsewhere.
std::vector<std::string> gather_texts(const std::string& text, const MpiSession& session) {
    int length = static_cast<int>(text.size());
    std::vector<int> lengths(static_cast<std::size_t>(session.size()));
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(lengths.size());
    int total = 0;
    for (std::size_t r = 0; r < lengths.size(); ++r) {
        offsets[r] = total;
        total += lengths[r];
    }
    std::string all(session.rank() == 0 ? static_cast<std::size_t>(total) : 0, '\0');
    MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                MPI_COMM_WORLD);
    std::vector<std::string> texts;
    if (session.rank() == 0)
        for (std::size_t r = 0; r < lengths.size(); ++r)
            texts.push_back(
                all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
    return texts;
}

// What a rank's runs depend on beyond the study's text: its data files and plug-in modules (as
// "data_file = SHA256 PATH" lines, so that a difference names the file), and what each external
// program announced of itself (its code's SHA-256 and version: Optimizer/Problem::identity_facts).
std::string rank_inputs(const PreparedStudy& study) {
    std::string text = context_data_files(study.problems);
    const auto add_module = [&text](const DataFile& module) {
        if (!module.sha256.empty())
            text += "data_file = " + module.sha256 + " " + module.path + '\n';
    };
    for (const PreparedAlgorithm& algorithm : study.algorithms)
        add_module(algorithm.module);
    for (const PreparedProblem& problem : study.problems)
        add_module(problem.module);
    for (const PreparedAlgorithm& algorithm : study.algorithms)
        if (const std::string facts = algorithm.optimizer->identity_facts(); !facts.empty())
            text += "program of " + algorithm.info.spec + " = " + facts + '\n';
    for (const PreparedProblem& problem : study.problems)
        if (const std::string facts = problem.problem->identity_facts(); !facts.empty())
            text += "program of " + problem.spec + " = " + facts + '\n';
    return text;
}

// The lines of `text` that `reference` does not have, each as "rank R: LINE".
std::vector<std::string> lines_not_in(const std::string& text, const std::string& reference,
                                      const std::string& rank) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (reference.find(line + '\n') == std::string::npos)
            lines.push_back(rank + ": " + line + " (rank 0 has another)");
    return lines;
}

} // namespace

std::vector<std::string> rank_data_differences(const PreparedStudy& study, const MpiSession& session) {
    const std::string mine = rank_inputs(study);
    const std::vector<std::string> texts = gather_texts(mine, session);
    std::vector<std::string> lines;
    for (std::size_t r = 1; r < texts.size(); ++r) {
        const std::string rank = "rank " + std::to_string(r);
        auto differences =
            data_file_differences(recorded_data_files(texts[r]), rank, recorded_data_files(mine), "rank 0");
        if (differences.empty() && texts[r] != mine)
            differences = lines_not_in(texts[r], mine, rank);
        if (differences.empty() && texts[r] != mine)
            differences.push_back(rank + " read fewer data files, plug-ins or programs than rank 0");
        lines.insert(lines.end(), differences.begin(), differences.end());
    }
    int refused = lines.empty() ? 0 : 1;
    MPI_Bcast(&refused, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (refused != 0 && session.rank() != 0)
        lines.push_back("rank 0 found data files that differ between ranks");
    return lines;
}

} // namespace mhb
