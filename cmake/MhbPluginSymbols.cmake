# Writes the symbols the mhbench executable exports to plug-in modules (ld's --dynamic-list), from
# what the libraries' objects define, so that the list follows the contract's headers instead of
# being kept by hand. Run at build time, after the libraries and before the executable's link
# (runner/CMakeLists.txt):
#   cmake -DNM=nm -DSOURCE_DIR=... -DOBJECT_LIST=file -DOUTPUT=file -P MhbPluginSymbols.cmake
# OBJECT_LIST names the libraries' objects, one a line. Exported:
#   - the vtable, VTT, typeinfo and typeinfo name of every class the contract's headers define,
#     from whichever object defines them: an unoptimised plug-in references its base's vtable
#     (the Problem constructor it inlines), and the one vtable of a class with an out-of-line
#     virtual function lives in mhbench;
#   - every function and variable (strong symbols only: the weak ones are inline code a plug-in
#     compiles itself) that a contract source defines in namespace mhb under a name its header
#     mentions: problems/objective.cpp for problems/objective.hpp, and so on.
# Names are matched in their mangled form (_ZN3mhb<length><name>..., _ZTVN3mhb<length><name>...):
# the first name after mhb:: is the class or the function.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/mhbenchContractHeaders.cmake)

# The first name after mhb:: of a mangled symbol, in OUT_NAME; OUT_KIND is "class-data" for a
# vtable, VTT or typeinfo, "entity" for a function or variable, empty for anything else.
function(mhb_symbol_first_name symbol out_kind out_name)
    set(${out_kind} "" PARENT_SCOPE)
    if(symbol MATCHES "^_ZT[VTIS]N3mhb([0-9]+)")
        set(kind class-data)
    elseif(symbol MATCHES "^_ZN[rVKO]*3mhb([0-9]+)")
        set(kind entity)
    else()
        return()
    endif()
    string(LENGTH "${CMAKE_MATCH_0}" prefix)
    string(SUBSTRING "${symbol}" ${prefix} ${CMAKE_MATCH_1} name)
    set(${out_kind} ${kind} PARENT_SCOPE)
    set(${out_name} ${name} PARENT_SCOPE)
endfunction()

# The classes and structs the headers define (not those they only declare), in OUT.
function(mhb_contract_classes out)
    set(classes "")
    foreach(header IN LISTS MHBENCH_CONTRACT_HEADERS)
        file(READ ${SOURCE_DIR}/${header} text)
        string(REGEX REPLACE "template[ \t\n]*<[^>]*>" "" text "${text}")
        string(REGEX REPLACE "enum[ \t]+(class|struct)" "enum" text "${text}")
        string(REGEX MATCHALL "(class|struct)[ \t]+[A-Za-z_][A-Za-z0-9_]*[^;{()]*{" found "${text}")
        foreach(definition IN LISTS found)
            string(REGEX MATCH "^(class|struct)[ \t]+([A-Za-z_][A-Za-z0-9_]*)" unused "${definition}")
            list(APPEND classes ${CMAKE_MATCH_2})
        endforeach()
    endforeach()
    list(REMOVE_DUPLICATES classes)
    set(${out} ${classes} PARENT_SCOPE)
endfunction()

# The header whose source compiled into OBJECT (.../mhb_problems.dir/core/rng.cpp.o for
# problems/core/rng.hpp), in OUT; empty when the object is not a contract source's.
function(mhb_header_of_object object out)
    set(${out} "" PARENT_SCOPE)
    string(REPLACE "/./" "/" object "${object}") # Ninja's spelling: mhb_problems.dir/./core/rng.cpp.o
    foreach(header IN LISTS MHBENCH_CONTRACT_HEADERS)
        string(REGEX REPLACE "^[a-z]+/(.*)\\.hpp$" "\\1" stem ${header})
        string(REPLACE "." "\\." stem_pattern ${stem})
        if(object MATCHES "\\.dir/${stem_pattern}\\.cpp\\.o(bj)?$")
            set(${out} ${header} PARENT_SCOPE)
            return()
        endif()
    endforeach()
endfunction()

# The symbols of OBJECT to export, appended to the list named by OUT.
function(mhb_exported_symbols object classes out)
    execute_process(COMMAND ${NM} -g --defined-only -p ${object} OUTPUT_VARIABLE table
        COMMAND_ERROR_IS_FATAL ANY)
    mhb_header_of_object(${object} header)
    if(header)
        file(READ ${SOURCE_DIR}/${header} header_text)
    endif()
    set(symbols ${${out}})
    string(REGEX MATCHALL "[0-9a-f]+ [A-Za-z] _Z(T[VTIS])?N[rVKO]*3mhb[^\n]*" lines "${table}")
    foreach(line IN LISTS lines)
        string(REGEX MATCH "^[0-9a-f]* ([A-Za-z]) (.*)$" unused "${line}")
        set(type ${CMAKE_MATCH_1})
        set(symbol ${CMAKE_MATCH_2})
        mhb_symbol_first_name(${symbol} kind name)
        if(kind STREQUAL "class-data" AND name IN_LIST classes)
            list(APPEND symbols ${symbol})
        elseif(kind STREQUAL "entity" AND header AND type MATCHES "^[TDRBG]$" AND
               header_text MATCHES "(^|[^A-Za-z0-9_])${name}([^A-Za-z0-9_]|$)")
            list(APPEND symbols ${symbol})
        endif()
    endforeach()
    set(${out} ${symbols} PARENT_SCOPE)
endfunction()

mhb_contract_classes(classes)
file(STRINGS ${OBJECT_LIST} objects)
set(symbols "")
foreach(object IN LISTS objects)
    mhb_exported_symbols(${object} "${classes}" symbols)
endforeach()
list(REMOVE_DUPLICATES symbols)
list(SORT symbols)
list(LENGTH symbols count)
if(count LESS 20)
    message(FATAL_ERROR "MhbPluginSymbols: only ${count} symbols to export from ${OBJECT_LIST}")
endif()
list(JOIN symbols ";\n    " body)
set(text "/* Generated by cmake/MhbPluginSymbols.cmake from the libraries' objects: the symbols of the
   plug-in contract (cmake/mhbenchContractHeaders.cmake) that the mhbench executable exports to
   plug-in modules, and nothing else. */\n{\n    ${body};\n};\n")
# Written every time it runs (after a library changed, when the executable relinks anyway), so that
# the build tool sees it newer than the libraries and does not run this again.
file(WRITE ${OUTPUT} "${text}")
