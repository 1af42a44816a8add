# Writes the generated version header (cmake/version.hpp.in) with the git commit of SOURCE_DIR and
# whether its tracked files have uncommitted changes, as they are now. MhbVersion.cmake runs it at
# configure time and, through the mhb_version target, at every build: a commit or an edit followed
# by `cmake --build` alone is recorded. configure_file leaves OUTPUT untouched when its text is
# unchanged, so a build with nothing new recompiles nothing.
#
# cmake -DSOURCE_DIR=... -DOUTPUT=... -DGIT_EXECUTABLE=... (may be empty) -DPROJECT_VERSION=...
#       -DCMAKE_BUILD_TYPE=... -DCMAKE_CXX_COMPILER_ID=... -DCMAKE_CXX_COMPILER_VERSION=... -P MhbWriteVersion.cmake
set(MHB_GIT_COMMIT "unknown")
set(MHB_GIT_DIRTY "unknown")
if(GIT_EXECUTABLE)
    execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
        WORKING_DIRECTORY ${SOURCE_DIR}
        OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE commit_rc)
    if(commit_rc EQUAL 0 AND commit)
        set(MHB_GIT_COMMIT ${commit})
    endif()
    # A number made from a dirty tree cannot be traced back to a commit alone. Untracked files
    # (the build directory among them) do not count.
    execute_process(COMMAND ${GIT_EXECUTABLE} status --porcelain --untracked-files=no
        WORKING_DIRECTORY ${SOURCE_DIR}
        OUTPUT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status_rc)
    if(status_rc EQUAL 0)
        if(status)
            set(MHB_GIT_DIRTY "yes")
        else()
            set(MHB_GIT_DIRTY "no")
        endif()
    endif()
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.hpp.in ${OUTPUT} @ONLY)
