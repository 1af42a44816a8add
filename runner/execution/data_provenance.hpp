// What the parts of one study computed separately must share beyond study.ini: the content of
// every data file they read (by SHA-256, as context.ini's "data_file = SHA256 PATH" lines record
// it) and the build that computed them (version, commit, dirty flag). `mhbench merge` checks its
// shards with these before joining them; a study.ini that names the same path says nothing about
// a file regenerated between two shards.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace mhb {

// The SHA-256 of each data file by path, from the "data_file" lines of a context.ini (or of
// context_data_files(): the files as they are now).
using DataFileHashes = std::map<std::string, std::string>;
DataFileHashes recorded_data_files(const std::string& context_text);

// One line per file that both hold with different contents, e.g. "/d/drive.csv: sha256 9b41.. in
// s2, sha256 3f2a.. in s1": `name` and `reference_name` say whose `hashes` and `reference` are.
std::vector<std::string> data_file_differences(const DataFileHashes& hashes, const std::string& name,
                                               const DataFileHashes& reference,
                                               const std::string& reference_name);

// "mhbench VERSION commit COMMIT (dirty: yes|no)" of a context.ini's latest session.
std::string recorded_build(const std::string& context_text);

} // namespace mhb
