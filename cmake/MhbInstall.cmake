# The installed C++ package (`cmake --install`), for plug-in modules built outside this tree:
#   include/mhbench/...            the plug-in contract's headers, and the headers they include
#   lib/cmake/mhbench/             mhbenchConfig.cmake, its version file, the exported targets
#                                  and mhbench_add_plugin() (mhbenchPlugin.cmake)
#   bin/mhbench                    the executable the modules are loaded into
#   share/mhbench/scripts/         the figure scripts it runs (runner/execution/companion_files.hpp)
#   share/mhbench/studies/         the preset study files, as text to copy (they are compiled in)
#   share/mhbench/python/          mhbench_study.py, a study directory as pandas DataFrames
#   share/mhbench/data/fluxmap/    the licence and provenance of the flux map compiled in
# mhbench::mhbench is headers only: a plug-in's calls into mhbench (Objective::evaluate, Rng,
# parameters) are resolved from the executable when it loads the module, so that the one copy of
# each function the runs use is mhbench's own (cmake/MhbPluginSymbols.cmake lists them).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The contract's headers (MHBENCH_CONTRACT_HEADERS).
include(${PROJECT_SOURCE_DIR}/cmake/mhbenchContractHeaders.cmake)

# The contract's sources are compiled each alone, out of the unity batches (cmake/MhbUnityBuild.cmake):
# the list of what the executable exports to plug-ins (cmake/MhbPluginSymbols.cmake) and its test
# (tests/plugin_modules/exported_contract_test.sh) tell which source defines a symbol by its object.
foreach(header IN LISTS MHBENCH_CONTRACT_HEADERS)
    string(REGEX REPLACE "\\.hpp$" ".cpp" source ${header})
    string(REGEX MATCH "^[a-z]+" folder ${header})
    if(EXISTS ${PROJECT_SOURCE_DIR}/${source})
        set_source_files_properties(${PROJECT_SOURCE_DIR}/${source} DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}
            PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
endforeach()

add_library(mhb_api INTERFACE)
add_library(mhbench::mhbench ALIAS mhb_api)
set_target_properties(mhb_api PROPERTIES EXPORT_NAME mhbench)
target_include_directories(mhb_api INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mhbench>)
target_link_libraries(mhb_api INTERFACE Eigen3::Eigen)
target_compile_features(mhb_api INTERFACE cxx_std_20)

foreach(header IN LISTS MHBENCH_CONTRACT_HEADERS)
    get_filename_component(folder ${header} DIRECTORY)
    install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mhbench/${folder})
endforeach()
# The executable as mhbench::cli, so that a plug-in's own tests can run it.
set_target_properties(mhbench PROPERTIES EXPORT_NAME cli)
install(TARGETS mhb_api mhbench EXPORT mhbenchTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(mhb_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/mhbench)
install(EXPORT mhbenchTargets NAMESPACE mhbench:: DESTINATION ${mhb_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/mhbenchConfig.cmake.in
    ${PROJECT_BINARY_DIR}/mhbenchConfig.cmake INSTALL_DESTINATION ${mhb_cmake_dir})
# 0.x: a minor version may change the contract, so find_package(mhbench 0.1) takes 0.1.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mhbenchConfigVersion.cmake COMPATIBILITY SameMinorVersion)
# mhbench_add_plugin() and the contract's fingerprint, which every plug-in computes at its build.
install(FILES ${PROJECT_BINARY_DIR}/mhbenchConfig.cmake ${PROJECT_BINARY_DIR}/mhbenchConfigVersion.cmake
    ${PROJECT_SOURCE_DIR}/cmake/mhbenchPlugin.cmake ${PROJECT_SOURCE_DIR}/cmake/mhbenchContract.cmake
    ${PROJECT_SOURCE_DIR}/cmake/mhbenchContractHeaders.cmake DESTINATION ${mhb_cmake_dir})

# What the executable needs or owes beside itself: the figure scripts it runs, found relative to it;
# the presets as files to start a study file from; the licence that travels with the shipped map.
foreach(script IN LISTS MHB_COMPANION_SCRIPTS)
    install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/${script} DESTINATION ${CMAKE_INSTALL_DATADIR}/mhbench/scripts)
endforeach()
# The Python module that loads a study into pandas (README, "Your results in Python"): not run by
# mhbench, imported by the user's scripts from here (sys.path.insert or PYTHONPATH).
install(FILES ${PROJECT_SOURCE_DIR}/scripts/python/mhbench_study.py DESTINATION ${CMAKE_INSTALL_DATADIR}/mhbench/python)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scripts/studies/ DESTINATION ${CMAKE_INSTALL_DATADIR}/mhbench/studies
    FILES_MATCHING PATTERN "*.ini")
install(FILES ${PROJECT_SOURCE_DIR}/problems/fluxmap/data/LICENSE-motulator
    ${PROJECT_SOURCE_DIR}/problems/fluxmap/data/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/mhbench/data/fluxmap)
