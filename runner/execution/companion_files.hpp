// Files mhbench runs or reads beside its executable: the figure scripts (scripts/plot_study.py,
// scripts/plot_flux_map.py). They are found relative to the running executable, at
// <directory of the executable>/../share/mhbench/<name>: the build copies them to
// <build>/share/mhbench/ (the executable is <build>/runner/mhbench) and `cmake --install` puts them
// in <prefix>/share/mhbench/ (the executable is <prefix>/bin/mhbench), so an installed mhbench
// needs neither the source nor the build tree, and a prefix can be moved as a whole.
#pragma once

#include <filesystem>
#include <string_view>

namespace mhb {

// The path of companion file `name` (e.g. "scripts/plot_study.py"), whether it exists or not (the
// caller says what is missing); relative to the working directory's share/mhbench/ if the
// executable's own path cannot be read.
std::filesystem::path companion_file(std::string_view name);

} // namespace mhb
