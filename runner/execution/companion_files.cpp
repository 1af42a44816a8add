#include "runner/execution/companion_files.hpp"

#include <system_error>

namespace mhb {

std::filesystem::path companion_file(std::string_view name) {
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec); // Linux
    const std::filesystem::path share = ec ? std::filesystem::path("share") / "mhbench"
                                           : executable.parent_path().parent_path() / "share" / "mhbench";
    return share / std::filesystem::path(name);
}

} // namespace mhb
