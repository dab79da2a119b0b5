# Debian 12 packages installed by scripts/bootstrap.sh (DESIGN §9).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(PkgConfig REQUIRED)
pkg_check_modules(MPFR REQUIRED IMPORTED_TARGET mpfr)
pkg_check_modules(GMP REQUIRED IMPORTED_TARGET gmp)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
find_package(fmt REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PNG REQUIRED)
find_package(Freetype REQUIRED)
find_package(Threads REQUIRED)
if(SOMA_BUILD_TESTS)
  find_package(Catch2 REQUIRED)
  include(Catch)
endif()
if(SOMA_BUILD_BENCH)
  find_package(benchmark REQUIRED)
  find_package(orocos_kdl QUIET)
endif()
# General-6R numerical alternatives (geometry/src/serial/general_6r_{ceres,nlopt}.cpp). NLopt's
# C++ build is the nlopt_cxx config (a plain find_package(NLopt) picks the C build: DESIGN §9).
find_package(Ceres REQUIRED)
find_package(NLopt CONFIG REQUIRED HINTS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/nlopt_cxx)
# URDF import of serial chains (io/src/urdf_file.cpp): urdfdom ships a CMake config in
# /usr/lib/<arch>/urdfdom/cmake (targets urdfdom::urdfdom_model, which brings console_bridge).
find_package(urdfdom CONFIG REQUIRED)
# Parallel parameter-space maps of cuspidal 3R arms (geometry/src/cuspidal/parameter_map.cpp):
# Debian's libtbb-dev (oneTBB 2021) ships TBBConfig.cmake with the target TBB::tbb.
find_package(TBB REQUIRED)
