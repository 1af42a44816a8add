#include "runner/distribution/launcher_environment.hpp"

#include <charconv>
#include <string_view>

namespace mhb {
namespace {

// The variable's value as a count >= `least`, or 0 when it is unset, malformed or smaller.
int number_in(const EnvironmentLookup& lookup, const char* name, int least) {
    const char* text = lookup(name);
    if (text == nullptr)
        return 0;
    const std::string_view value(text);
    int number = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
    return error == std::errc() && end == value.data() + value.size() && number >= least ? number : 0;
}

} // namespace

LaunchedProcesses launched_processes(const EnvironmentLookup& lookup) {
    LaunchedProcesses found;
    struct Size {
        const char* name;
        int least; // smallest value that shows a launch
    };
    for (const Size size :
         {Size{"OMPI_COMM_WORLD_SIZE", 1}, Size{"PMI_SIZE", 1}, Size{"SLURM_STEP_NUM_TASKS", 2}})
        if (const int count = number_in(lookup, size.name, size.least); count > found.count)
            found = {count, false, std::string(size.name) + "=" + lookup(size.name)};
    for (const char* rank_name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"})
        if (const int rank = number_in(lookup, rank_name, 1); rank > 0 && rank + 1 > found.count)
            found = {rank + 1, true, std::string(rank_name) + "=" + lookup(rank_name)};
    return found;
}

} // namespace mhb
