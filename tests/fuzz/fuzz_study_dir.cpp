// Fuzzes the study-directory readers (results/store/study_data.hpp): the input is cut into files of a fresh
// temporary directory, then load_study reads it; a directory with store.bin and no runs.csv is
// also resumed by a StudyWriter (reading store.bin), finished and read back. Bad files must give
// std::runtime_error, never a crash.
//
// Input: parts separated by the byte 0x1E; a part's first byte names its file ('0'..'9', or any
// byte modulo 10: study.ini, context.ini, algorithms.csv, runs.csv, curves.csv, checkpoints.csv,
// trajectories.csv, timings.csv, store.bin, .mhbench-study), the rest is its content. Nothing is written
// outside the directory, which is emptied for each input and removed at exit.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_writer.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::array<const char*, 10> file_names = {
    mhb::StudyFiles::study,        mhb::StudyFiles::context, mhb::StudyFiles::algorithms,
    mhb::StudyFiles::runs,         mhb::StudyFiles::curves,  mhb::StudyFiles::checkpoints,
    mhb::StudyFiles::trajectories, mhb::StudyFiles::timings, mhb::StudyFiles::store,
    mhb::StudyFiles::marker};

// One scratch directory per process, under $TMPDIR, made with mkdtemp and removed at exit.
class ScratchDirectory {
public:
    ScratchDirectory() {
        std::string pattern = (fs::temp_directory_path() / "mhb-fuzz-study-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr)
            std::abort();
        root_ = pattern;
    }
    ~ScratchDirectory() {
        std::error_code ec;
        fs::remove_all(root_, ec);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    // An empty study directory inside the scratch directory.
    [[nodiscard]] fs::path fresh() const {
        const fs::path dir = root_ / "study";
        fs::remove_all(dir);
        fs::create_directory(dir);
        return dir;
    }

private:
    fs::path root_;
};

void write(const fs::path& path, std::string_view content) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out)
        std::abort();
}

// The content of `path`, or "" when there is no such file.
std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const ScratchDirectory scratch;
    const fs::path dir = scratch.fresh();
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    std::size_t start = 0;
    while (start <= input.size()) {
        const std::size_t end = std::min(input.find('\x1e', start), input.size());
        const std::string_view part = input.substr(start, end - start);
        start = end + 1;
        if (part.empty())
            continue;
        const auto selector = static_cast<unsigned char>(part.front());
        const std::size_t file = selector >= '0' && selector <= '9'
                                     ? std::size_t{selector} - '0'
                                     : std::size_t{selector} % file_names.size();
        write(dir / file_names[file], part.substr(1));
    }

    try {
        (void)mhb::load_study(dir);
    } catch (const std::runtime_error&) {
    }
    if (!fs::exists(dir / mhb::StudyFiles::store) || fs::exists(dir / mhb::StudyFiles::runs))
        return 0;
    // An unfinished study: resumed from its store, finished, and read back.
    const std::string study_text = read(dir / mhb::StudyFiles::study);
    std::vector<std::string> parameter_columns; // those of trajectories.csv's header, if any
    const std::string trajectories = read(dir / mhb::StudyFiles::trajectories);
    const std::string header = trajectories.substr(0, trajectories.find('\n'));
    for (std::size_t i = 0, field = 0; i <= header.size() && parameter_columns.size() < 16; ++field) {
        const std::size_t comma = std::min(header.find(',', i), header.size());
        if (field >= 2)
            parameter_columns.push_back(header.substr(i, comma - i));
        i = comma + 1;
    }
    try {
        mhb::StudyWriter writer(dir, study_text, "fuzz", parameter_columns, false);
        writer.finish();
        (void)mhb::load_study(dir);
    } catch (const std::runtime_error&) {
    }
    return 0;
}
