// The marker .mhbench-study (its text: format, study.ini checksum, run count, rendered files) and
// what makes a directory a study (see study_marker.hpp).
#include "results/store/study_marker.hpp"

#include <filesystem>
#include <string>

#include "results/store/crc32c.hpp"
#include "results/store/study_files.hpp"

namespace mhb {
namespace fs = std::filesystem;

std::string study_checksum(std::string_view study_text) {
    return crc32c_hex(crc32c(study_text));
}

std::string rendered_file_facts(std::uint64_t size, std::uint32_t checksum) {
    return std::to_string(size) + " bytes, crc32c " + crc32c_hex(checksum);
}

std::string study_marker(std::string_view study_text, std::int64_t runs,
                         const std::vector<RenderedFile>& rendered) {
    std::string text = "mhbench study directory, format 3\n";
    if (runs < 0)
        return text;
    text += "study.ini crc32c = " + study_checksum(study_text) + "\nruns = " + std::to_string(runs) + '\n';
    for (const RenderedFile& file : rendered)
        text += file.name + " = " + rendered_file_facts(file.size, file.checksum) + '\n';
    return text;
}

bool is_study_directory(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir / StudyFiles::marker, ec))
        return true;
    // Without the marker (from before it, or lost): the study.ini and records of a study.
    return fs::exists(dir / StudyFiles::study, ec) &&
           (fs::exists(dir / StudyFiles::runs, ec) || fs::exists(dir / StudyFiles::store, ec) ||
            fs::exists(dir / StudyFiles::journal, ec));
}

} // namespace mhb
