# Precompiled headers: the library and test headers that nearly every source of a target parses
# (the standard library, Eigen, Boost.Program_options, GoogleTest) are parsed once per target instead
# of once per source. Compilation only: the objects and every number they compute are the same, and
# a target's PCH is private to it. Off with -DMHB_PRECOMPILE_HEADERS=OFF (e.g. for include-what-you-use).
option(MHB_PRECOMPILE_HEADERS "Precompile the headers most sources of a target include" ON)

# The standard headers most of our sources include.
set(mhb_pch_standard <algorithm> <cmath> <cstdint> <filesystem> <map> <memory> <optional> <stdexcept>
    <string> <string_view> <utility> <vector>)

function(mhb_precompile_headers target)
    if(MHB_PRECOMPILE_HEADERS)
        target_precompile_headers(${target} PRIVATE ${mhb_pch_standard} ${ARGN})
    endif()
endfunction()
