add_library(soma_warnings INTERFACE)
target_compile_options(soma_warnings INTERFACE -Wall -Wextra -Wno-psabi)

# Tests and studies compile at -O1 in Release (the last -O on the command line wins). Their cost
# is template instantiation over five scalars, not run time: measured on gf04_exp.cpp, -O3 52 s,
# -O2 30 s, -O1 26 s; the libraries and benchmarks keep -O3.
set(SOMA_CHECK_CODE_OPT "-O1" CACHE STRING "Optimisation flag of the tests and studies in Release")
add_library(soma_check_code INTERFACE)
target_compile_options(soma_check_code INTERFACE $<$<CONFIG:Release>:${SOMA_CHECK_CODE_OPT}>)

# Tests and studies are compiled in unity batches (see tests/CMakeLists.txt); OFF to compile each
# file on its own (e.g. to find which file an error is in).
option(SOMA_UNITY_BUILD "Compile tests and studies in unity batches" ON)
