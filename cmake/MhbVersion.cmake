# The version and git commit are recorded in every study's context file, so that a published
# number can be traced back to the code that made it.
find_package(Git QUIET)
set(MHB_GIT_COMMIT "unknown")
if(GIT_FOUND)
    execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
        WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
        OUTPUT_VARIABLE _mhb_commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _mhb_rc)
    if(_mhb_rc EQUAL 0 AND _mhb_commit)
        set(MHB_GIT_COMMIT ${_mhb_commit})
    endif()
endif()
configure_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/version.hpp.in
    ${CMAKE_CURRENT_BINARY_DIR}/generated/mhb_version.hpp @ONLY)
