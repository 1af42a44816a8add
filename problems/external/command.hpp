// The `cmd=` of an `external:` spec: split into words (no shell), and what of it joins a run's
// identity — the command line as written (it is in the spec), the SHA-256 of the program's code
// and the version the program announces.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"

namespace mhb::external {

// `text` split at blanks; words may be quoted with '...' or "..." to hold blanks, and the whole
// command may be quoted once more (`cmd='python3 model.py'`, one spec in a list). Throws
// std::invalid_argument for an empty command or an unclosed quote.
std::vector<std::string> split_command(const std::string& text);

// The files whose content is the program's code: every word that names an existing regular file
// (`python3 model.py weights.json` gives model.py and weights.json; `./model` gives ./model),
// except an installed interpreter in front of them (a first word found through PATH or under
// /usr/ or /bin/, like python3 or octave), whose updates are not the program's changes. When no
// other word names a file, the first word itself (resolved through PATH).
std::vector<std::string> code_files(const std::vector<std::string>& words);

// What messages call the program: the first of its code words as written (`scripts/x.py`, not
// `/usr/bin/python3`: a user knows their script, not the interpreter that runs it), else the
// first word.
std::string program_name(const std::vector<std::string>& words);

// `a=1;b=two` (the `params=` pass-through) as a map; std::invalid_argument naming `owner` for
// an item without '='.
std::map<std::string, std::string> split_params(const std::string& owner, const std::string& text);

// What joins the run identity: "sha256 <hex> <file>; ...; version <v>" (see the header comment).
std::string identity_facts(const std::vector<std::string>& words, const std::string& version);

// The parameters every `external:` spec declares (cmd, params, startup_timeout), problem or
// optimiser, and what they hold once validated (std::invalid_argument without cmd).
std::vector<ParameterInfo> common_parameters();
struct CommonOptions {
    std::string command; // the words joined by blanks, for messages
    std::vector<std::string> argv;
    std::map<std::string, std::string> parameters;
    std::chrono::duration<double> startup_timeout{10.0};
};
CommonOptions common_options(const ParameterValues& values);

} // namespace mhb::external
