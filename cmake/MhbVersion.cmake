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
# Whether the working tree had uncommitted changes when the build was configured: a number made
# from a dirty tree cannot be traced back to a commit alone.
set(MHB_GIT_DIRTY "unknown")
if(GIT_FOUND)
    execute_process(COMMAND ${GIT_EXECUTABLE} status --porcelain --untracked-files=no
        WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
        OUTPUT_VARIABLE _mhb_status OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _mhb_rc)
    if(_mhb_rc EQUAL 0)
        if(_mhb_status)
            set(MHB_GIT_DIRTY "yes")
        else()
            set(MHB_GIT_DIRTY "no")
        endif()
    endif()
endif()
configure_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/version.hpp.in
    ${CMAKE_CURRENT_BINARY_DIR}/generated/mhb_version.hpp @ONLY)
