// Small file helpers shared by the tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace mhb::test_support {

// The whole content of a file, byte for byte ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// A fresh, empty path under the temporary directory, named after `prefix`, `name` and the process
// id (tests that CTest runs in parallel, one process each, stay apart); removed when the test
// process exits.
inline std::filesystem::path fresh_temporary_path(const std::string& prefix, const std::string& name) {
    struct Removed {
        std::vector<std::filesystem::path> paths;
        ~Removed() {
            std::error_code ec;
            for (const auto& p : paths)
                std::filesystem::remove_all(p, ec);
        }
    };
    static Removed removed;
    const auto dir =
        std::filesystem::temp_directory_path() / (prefix + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    removed.paths.push_back(dir);
    return dir;
}

} // namespace mhb::test_support
