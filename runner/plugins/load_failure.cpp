#include "runner/plugins/load_failure.hpp"

#include <cstdlib>
#include <cxxabi.h>
#include <memory>

namespace mhb {
namespace {

// SYMBOL demangled, or as given when it is not a mangled C++ name (a C function's).
std::string demangled(const std::string& symbol) {
    int status = 0;
    const std::unique_ptr<char, void (*)(void*)> name(
        abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), &std::free);
    return status == 0 && name != nullptr ? std::string(name.get()) : symbol;
}

} // namespace

std::string load_failure(const std::string& reason) {
    // glibc: "PATH: undefined symbol: NAME", and ", version V" after a versioned one.
    const std::string marker = "undefined symbol: ";
    const auto at = reason.find(marker);
    if (at == std::string::npos)
        return " (" + reason + ")";
    const auto start = at + marker.size();
    const std::string symbol = reason.substr(start, reason.find_first_of(", \t\n", start) - start);
    return ": undefined symbol " + demangled(symbol) +
           " (a symbol mhbench does not export to plug-ins: build the plug-in against this mhbench's "
           "installed package, and call only what its headers declare)";
}

} // namespace mhb
