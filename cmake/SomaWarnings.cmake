add_library(soma_warnings INTERFACE)
target_compile_options(soma_warnings INTERFACE -Wall -Wextra -Wno-psabi)

# Tests and studies are not where run time goes: their compile cost is template instantiation over
# five scalars, and the optimiser is half of it. Measured with clang 14 (user CPU, one unity batch):
# studies 75.7 s at -O1 vs 40.6 s at -O0, line tests 51.6 vs 25.1, Study-quadric tests 44.4 vs 36.9.
# So they compile at -O0 (the last -O on the command line wins), except the code whose run time is
# measured in seconds (`soma_run_code`, -O1): the study files listed in studies/CMakeLists.txt (speed/accuracy sweeps,
# OMPL maps, float128 Lagrangians: the report took 199 s at -O0 against 73 s at -O1).
# The libraries and benchmarks keep -O3, except the float, long double, __float128 and mpfr
# instantiations of the libraries: -O1 (SOMA_LADDER_OPT, cmake/SomaInstantiate.cmake).
set(SOMA_CHECK_CODE_OPT "-O0" CACHE STRING "Optimisation flag of the tests and studies in Release")
set(SOMA_RUN_CODE_OPT "-O1" CACHE STRING "Optimisation flag of the tests and studies whose run time matters")
add_library(soma_check_code INTERFACE)
target_compile_options(soma_check_code INTERFACE $<$<CONFIG:Release>:${SOMA_CHECK_CODE_OPT}>)
add_library(soma_run_code INTERFACE)
target_compile_options(soma_run_code INTERFACE $<$<CONFIG:Release>:${SOMA_RUN_CODE_OPT}>)

# Tests and studies are compiled in unity batches (see tests/CMakeLists.txt); OFF to compile each
# file on its own (e.g. to find which file an error is in).
option(SOMA_UNITY_BUILD "Compile tests and studies in unity batches" ON)
# Batches of 8: the files of an area instantiate the same templates for the same scalars, and a larger
# batch instantiates them fewer times (measured 2026-12-02, clang 14, CCACHE_DISABLE, the lines and
# dynamics tests: 132 s of CPU in batches of 4, 104 s in batches of 8).
set(SOMA_UNITY_BATCH 8 CACHE STRING "Files per unity batch of the tests and studies")

# Issue 22: an unqualified sqrt(x) (sin, atan2, ...) in a template finds only the C library's
# ::sqrt(double) when S is long double or __float128 (builtin types: no argument-dependent lookup),
# and rounds the answer to double in silence; `using std::sqrt;` in the function fixes it. clang's
# -Wimplicit-float-conversion sees the narrowing in the instantiation. The library's instantiation
# TUs of long double, __float128 and mpfr and the ladder TUs (those three and float together) had
# none left after the audit of 2026-12-05 (papers/robustness.md), so there it is an error:
# soma_instantiate adds this to every unit but float's and double's (double -> float not audited).
# (Clang only: GCC has no -Wimplicit-float-conversion, and its -Wfloat-conversion was not audited.)
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  set(soma_wide_default "-Werror=implicit-float-conversion")
else()
  set(soma_wide_default "")
endif()
set(SOMA_WIDE_SCALAR_ERRORS "${soma_wide_default}" CACHE STRING
    "Flags of the library's long double, __float128, mpfr and ladder instantiation TUs")
