#include "runner/mpi/rank_data_check.hpp"

#include <mpi.h>

#include "runner/context.hpp"
#include "runner/data_provenance.hpp"

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

} // namespace

std::vector<std::string> rank_data_differences(const PreparedStudy& study, const MpiSession& session) {
    const std::string mine = context_data_files(study.problems);
    const std::vector<std::string> texts = gather_texts(mine, session);
    std::vector<std::string> lines;
    for (std::size_t r = 1; r < texts.size(); ++r) {
        const std::string rank = "rank " + std::to_string(r);
        auto differences =
            data_file_differences(recorded_data_files(texts[r]), rank, recorded_data_files(mine), "rank 0");
        if (differences.empty() && texts[r] != mine)
            differences.push_back(rank + " read other data files than rank 0");
        lines.insert(lines.end(), differences.begin(), differences.end());
    }
    int refused = lines.empty() ? 0 : 1;
    MPI_Bcast(&refused, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (refused != 0 && session.rank() != 0)
        lines.push_back("rank 0 found data files that differ between ranks");
    return lines;
}

} // namespace mhb
