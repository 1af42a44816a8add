#include "runner/execution/data_provenance.hpp"

#include <sstream>

#include "runner/execution/context.hpp"

namespace mhb {

DataFileHashes recorded_data_files(const std::string& context_text) {
    DataFileHashes hashes;
    std::istringstream in(context_text);
    const std::string key = "data_file = ";
    for (std::string line; std::getline(in, line);) {
        const auto space = line.find(' ', key.size());
        if (line.rfind(key, 0) == 0 && space != std::string::npos)
            hashes[line.substr(space + 1)] = line.substr(key.size(), space - key.size());
    }
    return hashes;
}

std::vector<std::string> data_file_differences(const DataFileHashes& hashes, const std::string& name,
                                               const DataFileHashes& reference,
                                               const std::string& reference_name) {
    std::vector<std::string> lines;
    for (const auto& [path, sha256] : hashes) {
        const auto other = reference.find(path);
        if (other != reference.end() && other->second != sha256)
            lines.push_back(path + ": sha256 " + sha256 + " in " + name + ", sha256 " + other->second +
                            " in " + reference_name);
    }
    return lines;
}

std::string recorded_build(const std::string& context_text) {
    return "mhbench " + context_field(context_text, "version") + " commit " +
           context_field(context_text, "git_commit") +
           " (dirty: " + context_field(context_text, "git_dirty_at_build") + ")";
}

} // namespace mhb
