// Before any run of an MPI job: every rank prepared the study from its own copy of the data files
// (on a cluster, each node reads its own file system), and a rank that read another content would
// compute runs that rank 0 stores under its own data's identity. The same holds for a plug-in
// module and an external program's code. Rank 0 gathers every rank's "data_file = SHA256 PATH"
// lines (runner/execution/context.hpp; plug-in modules among them) and external programs' facts, and
// compares them with its own.
#pragma once

#include <string>
#include <vector>

#include "runner/distribution/mpi/mpi_session.hpp"
#include "runner/study/study.hpp"

namespace mhb {

// Collective: every rank of `session` calls it with its prepared study. On rank 0, one line per
// difference ("PATH: sha256 A in rank 1, sha256 B in rank 0"); on the other ranks, one line saying
// that rank 0 refused when it did; none when every rank read the same data.
std::vector<std::string> rank_data_differences(const PreparedStudy& study, const MpiSession& session);

} // namespace mhb
