// A program started and left to itself: in a session of its own, its standard streams on
// /dev/null, not waited for and not tied to mhbench (the browser `mhbench report --open` starts
// stays open after mhbench ends). A grandchild runs it, so that nobody has to reap it. The other
// way to start a program (owned, ended with mhbench) is child_process.hpp.
#pragma once

#include <string>
#include <vector>

namespace mhb::process {

// Starts `argv` (argv[0] a path, as find_executable gives) and returns at once; whether exec
// succeeds is not known here. SIGPIPE is at its default in the program, whatever it is here.
void start_detached(const std::vector<std::string>& argv);

} // namespace mhb::process
