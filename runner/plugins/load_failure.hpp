// Why dlopen refused a module, worded for the plug-in's author (runner/plugins/plugin_loader.cpp).
// The usual cause is a symbol the module needs and the executable does not export to plug-ins
// (cmake/MhbPluginSymbols.cmake): the loader names it mangled (_ZTVN3mhb3FooE), so it is demangled
// (vtable for mhb::Foo) and followed by what to do about it.
#pragma once

#include <string>

namespace mhb {

// What follows "plugin PATH: cannot be loaded" for dlerror's text REASON:
//   ": undefined symbol vtable for mhb::Foo (a symbol mhbench does not export to plug-ins: ...)"
// for an undefined symbol, " (REASON)" for anything else.
std::string load_failure(const std::string& reason);

} // namespace mhb
