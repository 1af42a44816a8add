// context.ini: where and how a study was run (mhbench version, git commit, compiler, build
// type, threads, hardware threads, date and time UTC, host name, command line). Unlike study.ini
// it differs from machine to machine; it never influences results. Its fields are those of the
// latest session (the one that last resumed or extended the study); below them, one
// "session = DATE on HOST, mhbench VERSION commit COMMIT (dirty: yes|no): COMMAND" line per
// session that wrote into the directory, the first first, so that no resume hides the code that
// computed the earlier runs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "runner/study/prepared_components.hpp"

namespace mhb {

// This machine's host name ("unknown" when it cannot be read).
std::string host_name();
// The time now, UTC, in strftime's `format` (context.ini: "%Y-%m-%dT%H:%M:%SZ").
std::string utc_now(const char* format);

// `command_line` is argv as given (quoted here when an argument holds spaces).
std::string context_ini(int threads, const std::vector<std::string>& command_line);

// The value of the first "key = value" line of a text (context.ini, a lock file), if it has one.
std::optional<std::string> first_field(const std::string& text, const std::string& key);
// The value of the first "key = value" line of a context.ini (the latest session's), or "unknown".
std::string context_field(const std::string& context_text, const std::string& key);

// The key of the history lines.
inline constexpr const char* session_key = "session";

// The session lines of a context.ini: its history, or for one written before histories were kept,
// a line made from its fields ("" for "").
std::string context_sessions(const std::string& context_text);

// `current` (this session's context_ini and other lines) followed by the history: the session
// lines `earlier_sessions` (context_sessions of the directory's context.ini; of every shard for a
// merge) and this session's.
std::string context_with_history(const std::string& current, const std::string& earlier_sessions);

// "data_file = SHA256 PATH" for each data file of the study's problems (each file once, its path
// made absolute): which exact content a study read, for the record.
std::string context_data_files(const std::vector<PreparedProblem>& problems);

} // namespace mhb
