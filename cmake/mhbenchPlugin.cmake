# mhbench_add_plugin(NAME SOURCES a.cpp ...): a plug-in module NAME.so for `mhbench run --plugin`
# (runner/plugin_api.hpp). Shipped in the installed package and used in this tree's tests alike.
#   - a MODULE (dlopen'ed, never linked against), named NAME.so without the lib prefix;
#   - compiled against mhbench::mhbench: the same C++ standard and Eigen as mhbench;
#   - hidden visibility: the module exports its entry point (MHBENCH_PLUGIN) and nothing else, so
#     that its own classes never collide with mhbench's or another module's;
#   - mhbench's functions left undefined: the executable provides them when it loads the module.
function(mhbench_add_plugin name)
    cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
    if(NOT ARG_SOURCES)
        message(FATAL_ERROR "mhbench_add_plugin(${name}): give its SOURCES")
    endif()
    add_library(${name} MODULE ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE mhbench::mhbench)
    set_target_properties(${name} PROPERTIES PREFIX "" CXX_EXTENSIONS OFF
        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
endfunction()
