# Warnings go through an INTERFACE target linked by our own targets only, never as global flags,
# so that third-party headers and Debian's compile options stay untouched.
add_library(mhb_warnings INTERFACE)
target_compile_options(mhb_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion>)
option(MHB_WARNINGS_AS_ERRORS "Treat compiler warnings as errors" OFF)
if(MHB_WARNINGS_AS_ERRORS)
    target_compile_options(mhb_warnings INTERFACE -Werror)
endif()
