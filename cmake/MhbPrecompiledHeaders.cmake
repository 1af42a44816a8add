# Precompiled headers for the test executables: the standard headers, GoogleTest and Eigen, which
# every test source parses, are parsed once per executable. The libraries and the CLI do without:
# in unity batches (cmake/MhbUnityBuild.cmake) they parse each header once per batch already, and
# precompiling cost them more CPU than it saved (BENCHMARKS.md, "Build time"); without it, the
# compiler cache also hands the MPI build the release build's library objects. Compilation only:
# the objects and every number they compute are the same. Off with -DMHB_PRECOMPILE_HEADERS=OFF.
option(MHB_PRECOMPILE_HEADERS "Precompile the headers every test source includes" ON)

# The standard headers most of our sources include.
set(mhb_pch_standard <algorithm> <cmath> <cstdint> <filesystem> <map> <memory> <optional> <stdexcept>
    <string> <string_view> <utility> <vector>)

function(mhb_precompile_headers target)
    if(MHB_PRECOMPILE_HEADERS)
        target_precompile_headers(${target} PRIVATE ${mhb_pch_standard} ${ARGN})
    endif()
endfunction()
