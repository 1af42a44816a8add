#include "runner/distribution/mpi/mpi_session.hpp"

#include <mpi.h>
#include <stdexcept>
#include <string>

namespace mhb {

MpiSession::MpiSession() {
    int provided = MPI_THREAD_SINGLE;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED) {
        MPI_Finalize();
        throw std::runtime_error("MPI: the library gives thread level " + std::to_string(provided) +
                                 ", below MPI_THREAD_FUNNELED, which the runner's oneTBB threads need");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

bool MpiSession::broadcast(bool flag) const {
    int value = flag ? 1 : 0;
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value != 0;
}

MpiSession::~MpiSession() {
    MPI_Finalize();
}

} // namespace mhb
