# Unity builds: each target's sources are compiled in batches of sixteen, each batch one translation
# unit, so the inline code every source instantiates (the standard library's, Eigen's, GoogleTest's)
# is parsed, optimised and emitted once per batch instead of once per source. Compilation only: the
# objects compute the same numbers (no file is compiled with other flags). Off with
# -DMHB_UNITY_BUILD=OFF (e.g. for include-what-you-use, or to rebuild one edited file alone).
#
# What it asks of the sources: a batch is one translation unit, so the file-local names of a
# target's sources (anonymous namespaces, `static`) must not repeat between its files, and a
# using-directive at namespace scope would reach into the next file; the compiler refuses a repeated
# definition, and names that merely overload are avoided by giving each helper its file's own name.
# A source with its own compile definitions or options is compiled alone (CMake's rule).
option(MHB_UNITY_BUILD "Compile each target's sources in batches of sixteen (faster from scratch)" ON)
set(CMAKE_UNITY_BUILD ${MHB_UNITY_BUILD})
if(NOT DEFINED CMAKE_UNITY_BUILD_BATCH_SIZE)
    set(CMAKE_UNITY_BUILD_BATCH_SIZE 16)
endif()
