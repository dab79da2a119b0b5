# The installable package: `cmake --install build/release --prefix P` puts the public headers in
# P/include, the static libraries in P/lib, the `soma` command in P/bin, the CMake package
# (soma-config.cmake, exported targets soma::algebra, soma::geometry, soma::render, ..., soma::soma)
# in P/lib/cmake/soma, soma.pc in P/lib/pkgconfig and the LICENSE in P/share/doc/soma.
# Included from the top-level CMakeLists.txt after every add_subdirectory.
#
# A new library is one line in the list below: soma_package(<target> NAME <export name>
# HEADERS <its include/ folder>). It is installed and exported (with the soma libraries it links,
# e.g. soma_geometry's sub-libraries), joins soma::soma, and its link dependencies reach
# soma-config.cmake (find_dependency) and soma.pc; a dependency missing from the table of
# soma_package_dependency calls stops the configure step naming it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SOMA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/soma)
# Interface targets that only carry build flags (warnings, the -O0/-O1 of tests and studies).
# Linked PRIVATE to a static library they appear in its interface as $<LINK_ONLY:...>, which
# install(EXPORT) rejects; rewritten as $<BUILD_INTERFACE:$<LINK_ONLY:...>> they stay out of it.
set(SOMA_BUILD_ONLY_TARGETS soma_warnings soma_check_code soma_run_code)

# ---- the dependencies an exported target may name ---------------------------------------------
# soma_package_dependency(<imported target> FIND "<code for soma-config.cmake>"
#                         [PC <pkg-config module>] [LIBS <flags, when there is no module>])
function(soma_package_dependency target)
  cmake_parse_arguments(arg "" "FIND;PC;LIBS" "" ${ARGN})
  string(MAKE_C_IDENTIFIER "${target}" id)
  set_property(GLOBAL PROPERTY SOMA_DEP_${id}_FIND "${arg_FIND}")
  set_property(GLOBAL PROPERTY SOMA_DEP_${id}_PC "${arg_PC}")
  set_property(GLOBAL PROPERTY SOMA_DEP_${id}_LIBS "${arg_LIBS}")
  set_property(GLOBAL PROPERTY SOMA_DEP_${id}_KNOWN TRUE)
endfunction()
soma_package_dependency(Eigen3::Eigen FIND "find_dependency(Eigen3 3.4 NO_MODULE)" PC eigen3)
# A pkg-config module found as the imported target PkgConfig::<PREFIX> (cmake/SomaDependencies.cmake).
function(soma_package_pkg_dependency prefix module)
  soma_package_dependency(PkgConfig::${prefix} PC ${module} FIND "find_dependency(PkgConfig)
if(NOT TARGET PkgConfig::${prefix})
  pkg_check_modules(${prefix} REQUIRED QUIET IMPORTED_TARGET ${module})
endif()")
endfunction()
soma_package_pkg_dependency(MPFR mpfr)
soma_package_pkg_dependency(GMP gmp)
soma_package_pkg_dependency(OSMESA osmesa)
soma_package_dependency(PNG::PNG FIND "find_dependency(PNG)" PC libpng)
soma_package_dependency(Freetype::Freetype FIND "find_dependency(Freetype)" PC freetype2)
soma_package_dependency(Ceres::ceres FIND "find_dependency(Ceres)" LIBS -lceres)
soma_package_dependency(NLopt::nlopt_cxx PC nlopt_cxx
  FIND "find_dependency(NLopt CONFIG HINTS \"${NLopt_DIR}\")")
soma_package_dependency(TBB::tbb FIND "find_dependency(TBB)" PC tbb)
soma_package_dependency(fmt::fmt FIND "find_dependency(fmt)" PC fmt)
soma_package_dependency(nlohmann_json::nlohmann_json FIND "find_dependency(nlohmann_json)" PC nlohmann_json)
soma_package_dependency(urdfdom::urdfdom_model FIND "find_dependency(urdfdom CONFIG)" PC urdfdom)
soma_package_dependency(MPI::MPI_CXX FIND "find_dependency(MPI COMPONENTS CXX)" PC ompi-cxx)
soma_package_dependency(Threads::Threads FIND "find_dependency(Threads)" LIBS -pthread)

# ---- the libraries ---------------------------------------------------------------------------
# Global properties, so that the functions below can add to them: every installed library target,
# the ones named in soma_package lines (soma::soma links them), their header folders.
set_property(GLOBAL PROPERTY SOMA_PACKAGE_TARGETS "")
set_property(GLOBAL PROPERTY SOMA_PACKAGE_FRONT "")
set_property(GLOBAL PROPERTY SOMA_PACKAGE_HEADER_DIRS "")

# Install and export `target` as soma::<name> with its headers; a soma library it links is
# packaged too (as soma::<its name without soma_>). OPTIONAL: nothing when the target does not exist.
function(soma_package target)
  cmake_parse_arguments(arg "OPTIONAL" "NAME;HEADERS" "" ${ARGN})
  if(arg_OPTIONAL AND NOT TARGET ${target})
    return()
  endif()
  _soma_package_target(${target} ${arg_NAME})
  set_property(GLOBAL APPEND PROPERTY SOMA_PACKAGE_FRONT ${target})
  set_property(GLOBAL APPEND PROPERTY SOMA_PACKAGE_HEADER_DIRS ${arg_HEADERS})
endfunction()

function(_soma_package_target target name)
  get_property(packaged GLOBAL PROPERTY SOMA_PACKAGE_TARGETS)
  if(target IN_LIST packaged)
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY SOMA_PACKAGE_TARGETS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(NOT links)
    return()
  endif()
  foreach(b ${SOMA_BUILD_ONLY_TARGETS})
    string(REPLACE "$<LINK_ONLY:${b}>" "$<BUILD_INTERFACE:$<LINK_ONLY:${b}>>" links "${links}")
  endforeach()
  set_property(TARGET ${target} PROPERTY INTERFACE_LINK_LIBRARIES "${links}")
  foreach(dep ${links})
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" dep "${dep}")
    if(dep MATCHES "^soma_" AND TARGET ${dep} AND NOT dep IN_LIST SOMA_BUILD_ONLY_TARGETS)
      string(REGEX REPLACE "^soma_" "" dep_name ${dep})
      _soma_package_target(${dep} ${dep_name})
    endif()
  endforeach()
endfunction()

soma_package(soma_algebra NAME algebra HEADERS ${PROJECT_SOURCE_DIR}/algebra/include)
soma_package(soma_geometry NAME geometry HEADERS ${PROJECT_SOURCE_DIR}/geometry/include)
soma_package(soma_io NAME io HEADERS ${PROJECT_SOURCE_DIR}/io/include OPTIONAL)
soma_package(soma_render NAME render HEADERS ${PROJECT_SOURCE_DIR}/render/include)
soma_package(soma_scene NAME scene HEADERS ${PROJECT_SOURCE_DIR}/scene/include OPTIONAL)
soma_package(soma_sweep NAME sweep HEADERS ${PROJECT_SOURCE_DIR}/sweep/include OPTIONAL)

# soma::soma: everything, with the aggregate header <soma/soma.hpp> (include/soma/soma.hpp;
# the test "package: soma.hpp includes every public header" keeps it complete).
add_library(soma_all INTERFACE)
add_library(soma::soma ALIAS soma_all)
set_target_properties(soma_all PROPERTIES EXPORT_NAME soma)
target_include_directories(soma_all INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                                              $<INSTALL_INTERFACE:include>)
get_property(soma_front GLOBAL PROPERTY SOMA_PACKAGE_FRONT)
target_link_libraries(soma_all INTERFACE ${soma_front})
# The headers need C++20 with GNU extensions (__float128); CMake's default CXX_EXTENSIONS is ON.
target_compile_features(soma_all INTERFACE cxx_std_20)
set_property(GLOBAL APPEND PROPERTY SOMA_PACKAGE_TARGETS soma_all)
set_property(GLOBAL APPEND PROPERTY SOMA_PACKAGE_HEADER_DIRS ${PROJECT_SOURCE_DIR}/include)
get_property(SOMA_PACKAGE_TARGETS GLOBAL PROPERTY SOMA_PACKAGE_TARGETS)
get_property(SOMA_PACKAGE_HEADER_DIRS GLOBAL PROPERTY SOMA_PACKAGE_HEADER_DIRS)

install(TARGETS ${SOMA_PACKAGE_TARGETS} EXPORT soma-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir ${SOMA_PACKAGE_HEADER_DIRS})
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
endforeach()
# The command line (not exported: a program, not a library), wherever its CMakeLists.txt is.
install(TARGETS soma RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})

# ---- what a consumer must find: read from the exported targets' link libraries ----------------
# SOMA_FIND_DEPENDENCIES (soma-config.cmake), and for soma.pc the modules and flags, public
# (the headers need them: PUBLIC links) or private (LINK_ONLY: only the static libraries do).
set(SOMA_FIND_DEPENDENCIES "")
set(soma_pc_requires)
set(soma_pc_requires_private)
set(soma_pc_libs_extra)
set(soma_pc_libs_private)
set(soma_pc_cflags)
set(soma_found_deps)
foreach(t ${SOMA_PACKAGE_TARGETS})
  get_target_property(links ${t} INTERFACE_LINK_LIBRARIES)
  if(NOT links)
    set(links)
  endif()
  foreach(item ${links})
    set(private FALSE)
    if(item MATCHES "^\\$<LINK_ONLY:(.*)>$")
      set(item "${CMAKE_MATCH_1}")
      set(private TRUE)
    endif()
    if(item MATCHES "^\\$<BUILD_INTERFACE:" OR item IN_LIST SOMA_PACKAGE_TARGETS)
      continue()
    elseif(item MATCHES "^soma_")
      message(FATAL_ERROR "cmake/SomaInstall.cmake: ${t} links ${item}, which is not installed: "
                          "add a soma_package(${item} ...) line, or link it as $<BUILD_INTERFACE:${item}>")
    elseif(item MATCHES "::")
      string(MAKE_C_IDENTIFIER "${item}" id)
      get_property(known GLOBAL PROPERTY SOMA_DEP_${id}_KNOWN)
      if(NOT known)
        message(FATAL_ERROR "cmake/SomaInstall.cmake: ${t} links ${item}: add a "
                            "soma_package_dependency(${item} FIND ... PC|LIBS ...) line")
      endif()
      get_property(find GLOBAL PROPERTY SOMA_DEP_${id}_FIND)
      get_property(pc GLOBAL PROPERTY SOMA_DEP_${id}_PC)
      get_property(libs GLOBAL PROPERTY SOMA_DEP_${id}_LIBS)
      if(NOT item IN_LIST soma_found_deps)
        list(APPEND soma_found_deps ${item})
        string(APPEND SOMA_FIND_DEPENDENCIES "${find}\n")
      endif()
      if(pc AND private)
        list(APPEND soma_pc_requires_private ${pc})
      elseif(pc)
        list(APPEND soma_pc_requires ${pc})
      elseif(private)
        list(APPEND soma_pc_libs_private ${libs})
      else()
        list(APPEND soma_pc_libs_extra ${libs})
      endif()
    elseif(item MATCHES "^\\$<")
      message(FATAL_ERROR "cmake/SomaInstall.cmake: ${t} links '${item}', a generator expression "
                          "soma.pc cannot express")
    else()
      # A library file (OMPL_LIBRARIES is a path) or a plain name (quadmath).
      set(flag "${item}")
      if(IS_ABSOLUTE "${item}")
        get_filename_component(dir "${item}" DIRECTORY)
        get_filename_component(name "${item}" NAME_WE)
        string(REGEX REPLACE "^lib" "" name "${name}")
        set(flag "-L${dir};-l${name}")
      elseif(NOT item MATCHES "^-")
        set(flag "-l${item}")
      endif()
      if(private)
        list(APPEND soma_pc_libs_private ${flag})
      else()
        list(APPEND soma_pc_libs_extra ${flag})
      endif()
    endif()
  endforeach()
  get_target_property(options ${t} INTERFACE_COMPILE_OPTIONS)
  if(options)
    foreach(option ${options})
      if(option MATCHES "\\$<")
        message(FATAL_ERROR "cmake/SomaInstall.cmake: ${t} has the compile option '${option}', a "
                            "generator expression soma.pc cannot express")
      endif()
      string(REGEX REPLACE "^SHELL:" "" option "${option}")
      list(APPEND soma_pc_cflags "${option}")
    endforeach()
  endif()
endforeach()
# A module both public and private is public.
foreach(list soma_pc_requires soma_pc_requires_private soma_pc_libs_extra soma_pc_libs_private soma_pc_cflags)
  list(REMOVE_DUPLICATES ${list})
endforeach()
list(REMOVE_ITEM soma_pc_requires_private ${soma_pc_requires})
list(REMOVE_ITEM soma_pc_libs_private ${soma_pc_libs_extra})

# The static libraries in link order (a library before the ones it links): depth-first over
# the soma targets each one links, reversed post-order.
set_property(GLOBAL PROPERTY SOMA_LINK_POSTORDER "")
function(_soma_link_visit t)
  get_property(done GLOBAL PROPERTY SOMA_LINK_POSTORDER)
  if(t IN_LIST done OR t IN_LIST visiting)
    return()
  endif()
  list(APPEND visiting ${t})
  get_target_property(links ${t} INTERFACE_LINK_LIBRARIES)
  if(links)
    foreach(item ${links})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
      if(item IN_LIST SOMA_PACKAGE_TARGETS)
        _soma_link_visit(${item})
      endif()
    endforeach()
  endif()
  set_property(GLOBAL APPEND PROPERTY SOMA_LINK_POSTORDER ${t})
endfunction()
foreach(t ${SOMA_PACKAGE_TARGETS})
  _soma_link_visit(${t})
endforeach()
get_property(soma_link_order GLOBAL PROPERTY SOMA_LINK_POSTORDER)
list(REVERSE soma_link_order)
set(soma_pc_libs "-L\${libdir}")
foreach(t ${soma_link_order})
  get_target_property(type ${t} TYPE)
  if(type STREQUAL "STATIC_LIBRARY")
    list(APPEND soma_pc_libs "-l$<TARGET_FILE_BASE_NAME:${t}>")
  endif()
endforeach()
list(APPEND soma_pc_libs ${soma_pc_libs_extra})

# soma.pc: prefix relative to the file, so that `cmake --install --prefix P` works for any P.
file(RELATIVE_PATH SOMA_PC_PREFIX "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
string(REGEX REPLACE "/$" "" SOMA_PC_PREFIX "\${pcfiledir}/${SOMA_PC_PREFIX}")
list(JOIN soma_pc_requires " " SOMA_PC_REQUIRES)
list(JOIN soma_pc_requires_private " " SOMA_PC_REQUIRES_PRIVATE)
list(JOIN soma_pc_libs " " SOMA_PC_LIBS)
list(JOIN soma_pc_libs_private " " SOMA_PC_LIBS_PRIVATE)
list(JOIN soma_pc_cflags " " SOMA_PC_CFLAGS)
configure_file(${CMAKE_CURRENT_LIST_DIR}/soma.pc.in ${CMAKE_BINARY_DIR}/soma.pc.in @ONLY)
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/soma.pc INPUT ${CMAKE_BINARY_DIR}/soma.pc.in)
install(FILES ${CMAKE_BINARY_DIR}/soma.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# soma-config.cmake, soma-config-version.cmake (0.1.x satisfies find_package(soma 0.1); before
# 1.0 a minor version may break the API), soma-targets.cmake.
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/soma-config.cmake.in
                              ${CMAKE_BINARY_DIR}/soma-config.cmake
                              INSTALL_DESTINATION ${SOMA_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/soma-config-version.cmake
                                 COMPATIBILITY SameMinorVersion)
install(EXPORT soma-targets NAMESPACE soma:: DESTINATION ${SOMA_INSTALL_CMAKEDIR})
install(FILES ${CMAKE_BINARY_DIR}/soma-config.cmake ${CMAKE_BINARY_DIR}/soma-config-version.cmake
        DESTINATION ${SOMA_INSTALL_CMAKEDIR})
