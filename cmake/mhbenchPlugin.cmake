# mhbench_add_plugin(NAME SOURCES a.cpp ...): a plug-in module NAME.so for `mhbench run --plugin`
# (runner/plugin_api.hpp). Shipped in the installed package and used in this tree's tests alike.
#   - a MODULE (dlopen'ed, never linked against), named NAME.so without the lib prefix;
#   - compiled against mhbench::mhbench: the same C++ standard and Eigen as mhbench;
#   - hidden visibility: the module exports its entry point (MHBENCH_PLUGIN) and nothing else, so
#     that its own classes never collide with mhbench's or another module's;
#   - mhbench's functions left undefined: the executable provides them when it loads the module;
#   - the contract's fingerprint taken from the headers it is really compiled against
#     (mhbench_contract_fingerprint).
# The depfile of the fingerprint's command is written by the compiler, with absolute paths: CMake
# rewrites it for Ninja (policy CMP0116; functions keep the policies of their definition).
cmake_policy(SET CMP0116 NEW)

function(mhbench_add_plugin name)
    cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
    if(NOT ARG_SOURCES)
        message(FATAL_ERROR "mhbench_add_plugin(${name}): give its SOURCES")
    endif()
    add_library(${name} MODULE ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE mhbench::mhbench)
    set_target_properties(${name} PROPERTIES PREFIX "" CXX_EXTENSIONS OFF
        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
    mhbench_contract_fingerprint(${name})
endfunction()

# mhbench_contract_fingerprint(TARGET): TARGET is compiled with MHB_PLUGIN_CONTRACT, the fingerprint
# of the contract's headers (mhbenchContract.cmake) as its compiler resolves each of them with its
# include directories and definitions (and CMAKE_CXX_FLAGS), in a generated header it
# force-includes. Worked out again whenever one of those headers changes (the compiler's depfile).
# mhbench's own build calls it for the library that compares fingerprints (runner/CMakeLists.txt),
# so that both sides compute theirs the same way. The directories of an imported mhbench::mhbench
# are system directories in the real compile, searched after every -I: the probe searches them so.
function(mhbench_contract_fingerprint target)
    set(dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_contract)
    set(probe ${dir}/probe.cpp)
    set(header ${dir}/mhbench_contract.hpp)
    include(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/mhbenchContractHeaders.cmake)
    list(TRANSFORM MHBENCH_CONTRACT_HEADERS REPLACE "(.+)" "#include \"\\1\"\n" OUTPUT_VARIABLE lines)
    list(JOIN lines "" probe_text)
    file(CONFIGURE OUTPUT ${probe} CONTENT "${probe_text}")
    set(includes "$<TARGET_PROPERTY:${target},INCLUDE_DIRECTORIES>")
    set(definitions "$<TARGET_PROPERTY:${target},COMPILE_DEFINITIONS>")
    set(system "")
    if(TARGET mhbench::mhbench)
        get_target_property(imported mhbench::mhbench IMPORTED)
    endif()
    if(imported)
        set(system_includes "$<TARGET_PROPERTY:mhbench::mhbench,INTERFACE_INCLUDE_DIRECTORIES>")
        set(system "$<$<NOT:$<BOOL:$<TARGET_PROPERTY:${target},NO_SYSTEM_FROM_IMPORTED>>>:\
$<$<BOOL:${system_includes}>:-isystem$<JOIN:${system_includes},;-isystem>>>")
    endif()
    separate_arguments(flags NATIVE_COMMAND "${CMAKE_CXX_FLAGS}")
    add_custom_command(OUTPUT ${header}
        COMMAND ${CMAKE_CXX_COMPILER} ${flags} ${CMAKE_CXX20_STANDARD_COMPILE_OPTION}
                "$<$<BOOL:${definitions}>:-D$<JOIN:${definitions},;-D>>"
                "$<$<BOOL:${includes}>:-I$<JOIN:${includes},;-I>>" "${system}"
                -M -MT ${header} -MF ${dir}/probe.d ${probe}
        COMMAND ${CMAKE_COMMAND} -DDEPENDENCIES=${dir}/probe.d -DOUTPUT=${header}
                -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/mhbenchContract.cmake
        DEPENDS ${probe} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/mhbenchContract.cmake
                ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/mhbenchContractHeaders.cmake
        DEPFILE ${dir}/probe.d
        COMMENT "Fingerprinting the plug-in contract's headers as ${target} includes them"
        COMMAND_EXPAND_LISTS VERBATIM)
    target_sources(${target} PRIVATE ${header})
    # SHELL: keeps the pair together (CMake would merge two targets' lone `-include`s).
    target_compile_options(${target} PRIVATE "SHELL:-include ${header}")
endfunction()
