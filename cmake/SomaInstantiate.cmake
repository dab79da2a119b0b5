# The instantiation rule: how soma's templates are compiled for the five scalars.
#
# soma's templates are defined in headers and explicitly instantiated for the scalar ladder
# (float, double, long double, __float128, mpfr::mpreal), so that users and tests compile none of
# the heavy code. One rule does it for every concept:
#
#   1. The public header (soma/<layer>/<sub>/<concept>.hpp) declares the templates and ends with
#      `extern template` declarations for the five scalars (SOMA_FOR_EACH_SCALAR), so code that
#      includes it does not instantiate them again.
#   2. The definitions and one macro live in an implementation header, <concept>_impl.hpp:
#      private (src/<sub>/<concept>_impl.hpp) or public (include/.../<concept>_impl.hpp) when
#      other code needs the definitions. The macro is named SOMA_INSTANTIATE_<CONCEPT> (the
#      concept name in capitals) and expands, inside `namespace soma`, to the explicit
#      instantiation definitions for one scalar S:
#
#        #define SOMA_INSTANTIATE_LINE(S) \
#          template class Line<S>;        \
#          template S distance<S>(const Line<S>&, const Line<S>&);
#
#   3. The CMakeLists.txt of the library lists the concepts:
#
#        soma_instantiate(TARGET soma_geometry_serial IMPL soma/geometry/serial/general_6r_impl.hpp)
#        soma_instantiate(TARGET soma_geometry_lines NAME lines
#                         IMPL src/lines/line_impl.hpp src/lines/regulus_impl.hpp ...)
#
#      Each call writes one translation unit per scalar, ${CMAKE_CURRENT_BINARY_DIR}/inst/<NAME>_<scalar>.cpp
#      (<scalar>: float, double, long_double, float128, mpfr; NAME defaults to the concept of
#      the only IMPL), which includes every IMPL header and expands each one's macro for that scalar:
#
#        #include "src/lines/line_impl.hpp"
#        namespace soma { SOMA_INSTANTIATE_LINE(float) }
#
#      and adds it to TARGET. An IMPL path is relative to the calling CMakeLists.txt's folder or to
#      TARGET's include path. SCALARS <scalar>... restricts the ladder (default: all five).
#      A heavy concept gets a call of its own; light concepts of one sub-area share a call (their
#      *_impl.hpp then share a TU, so their file-local helpers must not have the same names).
#      LADDER (for light concepts, whose TUs cost mostly their headers): two TUs instead of five,
#      <NAME>_double.cpp and <NAME>_ladder.cpp with the other four scalars (one parse, not four).
#
# One TU per scalar keeps the two CI cores busy on the heavy concepts (general 6R, Stewart, the
# dynamics) and lets each scalar have its own flags: SOMA_SCALAR_OPT_<scalar>, below.
# Hand-written *_<scalar>.cpp stubs and SOMA_FOR_EACH_SCALAR in a .cpp are no longer used; code
# that is not a template (or only for double) stays in an ordinary src/<sub>/*.cpp.

set(SOMA_SCALARS float double long_double float128 mpfr)
set(SOMA_SCALAR_TYPE_float "float")
set(SOMA_SCALAR_TYPE_double "double")
set(SOMA_SCALAR_TYPE_long_double "long double")
set(SOMA_SCALAR_TYPE_float128 "__float128")
set(SOMA_SCALAR_TYPE_mpfr "mpfr::mpreal")

# Optimisation of each scalar's instantiations in Release. Only double is benchmarked and runs the
# long sweeps; the other four are for accuracy, so they compile at SOMA_LADDER_OPT (-O1): 10-20 %
# less compile CPU per TU (clang 14; the numbers: git log of this file).
# scripts/bench.sh configures -DSOMA_LADDER_OPT=-O3, so the benchmark table compares the scalars
# at one level.
set(SOMA_LADDER_OPT "-O1" CACHE STRING
    "Optimisation flag of the float, long double, __float128 and mpfr instantiations in Release")
foreach(scalar IN LISTS SOMA_SCALARS)
  if(NOT scalar STREQUAL "double")
    set(SOMA_SCALAR_OPT_${scalar} "${SOMA_LADDER_OPT}")
  endif()
endforeach()

# Concepts (their NAMEs) instantiated for double only in this build: empty (the whole ladder). A
# build that needs only some callers may list the concepts they call in no scalar but double to save
# their ladder: the `fuzz` preset lists those that neither its sanitized tests nor `soma` call in
# another scalar (CMakePresets.json; scripts/test.sh says which and why). A target that needs one of
# them in another scalar then fails to link, naming the symbol.
set(SOMA_INSTANTIATE_DOUBLE_ONLY "" CACHE STRING
    "Concepts (soma_instantiate NAMEs) instantiated for double only (the fuzz preset)")

function(soma_instantiate)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "LADDER" "TARGET;NAME" "IMPL;SCALARS")
  if(NOT ARG_TARGET OR NOT ARG_IMPL OR ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "soma_instantiate(TARGET <target> [NAME <name>] IMPL <concept>_impl.hpp... "
                        "[SCALARS <scalar>...] [LADDER]): got '${ARGV}'")
  endif()
  if(NOT ARG_SCALARS)
    set(ARG_SCALARS ${SOMA_SCALARS})
  endif()
  set(includes "")
  set(macros "")
  foreach(impl IN LISTS ARG_IMPL)
    get_filename_component(file ${impl} NAME)
    if(NOT file MATCHES "^(.+)_impl\\.hpp$")
      message(FATAL_ERROR "soma_instantiate: '${impl}' is not named <concept>_impl.hpp")
    endif()
    set(concept ${CMAKE_MATCH_1})
    if(NOT ARG_NAME)
      set(ARG_NAME ${concept})
    endif()
    string(TOUPPER "SOMA_INSTANTIATE_${concept}" macro)
    string(APPEND includes "#include \"${impl}\"\n")
    string(APPEND macros "@macro@(${macro})\n")
  endforeach()
  if(ARG_NAME IN_LIST SOMA_INSTANTIATE_DOUBLE_ONLY)
    set(ARG_SCALARS double)
  endif()
  get_property(seen GLOBAL PROPERTY SOMA_INSTANTIATE_NAMES)
  if("${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}" IN_LIST seen)
    message(FATAL_ERROR "soma_instantiate: NAME '${ARG_NAME}' used twice in ${CMAKE_CURRENT_SOURCE_DIR}")
  endif()
  set_property(GLOBAL APPEND PROPERTY SOMA_INSTANTIATE_NAMES "${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}")
  # The TUs: one per scalar, or with LADDER, double alone and the other scalars together.
  set(units "")
  foreach(scalar IN LISTS ARG_SCALARS)
    if(NOT DEFINED SOMA_SCALAR_TYPE_${scalar})
      message(FATAL_ERROR "soma_instantiate(${ARG_NAME}): unknown scalar '${scalar}' "
                          "(the ladder: ${SOMA_SCALARS})")
    endif()
    if(ARG_LADDER AND NOT scalar STREQUAL "double")
      if(NOT "ladder" IN_LIST units)
        list(APPEND units ladder)
      endif()
      list(APPEND scalars_ladder ${scalar})
      set(SOMA_SCALAR_OPT_ladder "${SOMA_SCALAR_OPT_${scalar}}")
    else()
      list(APPEND units ${scalar})
      set(scalars_${scalar} ${scalar})
    endif()
  endforeach()
  foreach(unit IN LISTS units)
    set(body "")
    set(types "")
    foreach(scalar IN LISTS scalars_${unit})
      set(type "${SOMA_SCALAR_TYPE_${scalar}}")
      string(REGEX REPLACE "@macro@\\(([A-Z0-9_]+)\\)" "\\1(${type})" one "${macros}")
      string(APPEND body "${one}")
      list(APPEND types "${type}")
    endforeach()
    list(JOIN types ", " types)
    set(tu ${CMAKE_CURRENT_BINARY_DIR}/inst/${ARG_NAME}_${unit}.cpp)
    file(CONFIGURE OUTPUT ${tu} @ONLY CONTENT
"// Generated by soma_instantiate (cmake/SomaInstantiate.cmake): ${ARG_NAME} for ${types}.
${includes}
namespace soma {
${body}}  // namespace soma
")
    target_sources(${ARG_TARGET} PRIVATE ${tu})
    set_source_files_properties(${tu} TARGET_DIRECTORY ${ARG_TARGET} PROPERTIES
                                INCLUDE_DIRECTORIES ${CMAKE_CURRENT_SOURCE_DIR})
    if(SOMA_SCALAR_OPT_${unit})  # after the build type's -O3 on the command line: the last -O wins
      set_source_files_properties(${tu} TARGET_DIRECTORY ${ARG_TARGET} PROPERTIES
                                  COMPILE_OPTIONS "$<$<CONFIG:Release>:${SOMA_SCALAR_OPT_${unit}}>")
    endif()
    if(NOT unit MATCHES "^(float|double)$")  # a wide scalar narrowed to double fails (SomaWarnings.cmake)
      set_property(SOURCE ${tu} TARGET_DIRECTORY ${ARG_TARGET} APPEND PROPERTY
                   COMPILE_OPTIONS ${SOMA_WIDE_SCALAR_ERRORS})
    endif()
  endforeach()
endfunction()
