# The version and git commit are recorded in every study's context file, so that a published
# number can be traced back to the code that made it. The commit and the dirty flag are read when
# mhbench is built, not when CMake configures (MhbWriteVersion.cmake): the mhb_version target runs
# at every build and rewrites generated/mhb_version.hpp only when they changed.
find_package(Git QUIET)
set(MHB_VERSION_HEADER ${CMAKE_CURRENT_BINARY_DIR}/generated/mhb_version.hpp)
set(mhb_write_version
    ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR} -DOUTPUT=${MHB_VERSION_HEADER}
    -DGIT_EXECUTABLE=${GIT_EXECUTABLE} -DPROJECT_VERSION=${PROJECT_VERSION} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
    -DCMAKE_CXX_COMPILER_ID=${CMAKE_CXX_COMPILER_ID} -DCMAKE_CXX_COMPILER_VERSION=${CMAKE_CXX_COMPILER_VERSION}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/MhbWriteVersion.cmake)
# At configure time too, so that the header exists for tools that read compile_commands.json.
execute_process(COMMAND ${mhb_write_version} COMMAND_ERROR_IS_FATAL ANY)
# Every library that includes the header depends on this target (runner/CMakeLists.txt).
add_custom_target(mhb_version COMMAND ${mhb_write_version} BYPRODUCTS ${MHB_VERSION_HEADER} VERBATIM)
