# ctest -R package: install the build into a temporary prefix, build tests/consumer (a copy, in a
# temporary folder) against it with find_package(soma) and the build's compiler, run it, and
# check that soma.pc resolves and links the same program.
# Usage: cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DCXX=... [-DLAUNCHER=...]
#              -DGENERATOR=... -DSOMA_EXE=<the built soma command> -DPKG_CONFIG=... -P consumer.cmake
cmake_minimum_required(VERSION 3.25)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${rc}):\n  ${ARGN}\n${out}")
  endif()
  string(STRIP "${out}" out)
  set(out "${out}" PARENT_SCOPE)
endfunction()

if(NOT EXISTS "${SOMA_EXE}")
  message(FATAL_ERROR "${SOMA_EXE} is not built: build the libraries and the soma command first "
                      "(cmake --build ${BUILD_DIR})")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# The installed tree.
file(GLOB_RECURSE libdirs LIST_DIRECTORIES true ${prefix}/*/cmake/soma)
list(GET libdirs 0 cmake_dir)
get_filename_component(libdir ${cmake_dir}/../.. ABSOLUTE)
foreach(f include/soma/soma.hpp include/soma/algebra/scalar.hpp include/soma/geometry/serial/closed_form_ik.hpp
          include/soma/render/scene.hpp bin/soma share/doc/soma/LICENSE)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "cmake --install: ${prefix}/${f} is missing")
  endif()
endforeach()
foreach(f cmake/soma/soma-config.cmake cmake/soma/soma-config-version.cmake cmake/soma/soma-targets.cmake
          pkgconfig/soma.pc libsoma_algebra.a libsoma_render.a libsoma_geometry_serial.a)
  if(NOT EXISTS ${libdir}/${f})
    message(FATAL_ERROR "cmake --install: ${libdir}/${f} is missing")
  endif()
endforeach()
run("the installed soma command" ${prefix}/bin/soma study list)

# The consumer, configured in a folder of its own, finding soma only in the prefix.
file(COPY ${CONSUMER_DIR}/ DESTINATION ${WORK_DIR}/src)
set(launcher)
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configure the consumer" ${CMAKE_COMMAND} -S ${WORK_DIR}/src -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} ${launcher} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${WORK_DIR}/build/CMakeCache.txt soma_dir REGEX "^soma_DIR:")
if(NOT soma_dir STREQUAL "soma_DIR:PATH=${cmake_dir}")
  message(FATAL_ERROR "the consumer found soma elsewhere: ${soma_dir} (expected ${cmake_dir})")
endif()
run("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
set(expect "PUMA 560, method pieper: 8 postures \\(8 expected\\), 0 with FK off the pose, q0 found, certified")
run("run the consumer" ${WORK_DIR}/build/consumer)
if(NOT out MATCHES "${expect}")
  message(FATAL_ERROR "consumer printed\n${out}\nexpected /${expect}/")
endif()
message(STATUS "find_package(soma) consumer: ${out}")

# soma.pc: resolves, and links the consumer's object file into a program that runs the same.
set(ENV{PKG_CONFIG_PATH} ${libdir}/pkgconfig)
run("pkg-config --cflags --libs soma" ${PKG_CONFIG} --cflags --libs soma)
if(NOT out MATCHES "-I[^ ]*include" OR NOT out MATCHES "-lsoma_algebra")
  message(FATAL_ERROR "pkg-config --cflags --libs soma: no -I or -lsoma_algebra in '${out}'")
endif()
message(STATUS "pkg-config --cflags --libs soma: ${out}")
run("pkg-config --static --libs soma" ${PKG_CONFIG} --static --libs soma)
separate_arguments(libs UNIX_COMMAND "${out}")
file(GLOB_RECURSE object ${WORK_DIR}/build/CMakeFiles/consumer.dir/*.o)
run("link the consumer with pkg-config --static --libs soma" ${CXX} ${object} ${libs} -o ${WORK_DIR}/consumer-pc)
run("run the pkg-config-linked consumer" ${WORK_DIR}/consumer-pc)
if(NOT out MATCHES "${expect}")
  message(FATAL_ERROR "pkg-config-linked consumer printed\n${out}\nexpected /${expect}/")
endif()
