# SPDX-License-Identifier: MIT
# ctest driver: install the build tree into a scratch prefix, build the consumer
# project against it, run it on the teapot and expect 32 patches, its
# OpenMesh round trip (the installed opt-in header) to give the mesh back,
# and on an IGES torus, read by the installed STEP/IGES reader beside the
# library.
set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()
# Runs a consumer program on the teapot; fails unless it prints `expected`.
function(expect_output program expected)
  execute_process(COMMAND ${WORK_DIR}/build/${program} ${SOURCE_DIR}/data/models/teapot.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  string(STRIP "${out}" out)
  if(rc OR NOT out STREQUAL "${expected}")
    message(FATAL_ERROR "${program} printed '${out}' (status ${rc}), expected ${expected}")
  endif()
endfunction()
expect_output(consumer 32)
message(STATUS "consumer built against the installed package reports 32 patches")
expect_output(consumer_openmesh same)
message(STATUS "the installed <seamless/mesh/openmesh.h> round-trips the teapot")
execute_process(COMMAND ${WORK_DIR}/build/consumer ${SOURCE_DIR}/data/models/cad/torus.igs
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(STRIP "${out}" out)
if(rc OR NOT out MATCHES "^[1-9][0-9]*$")
  message(FATAL_ERROR "consumer on torus.igs printed '${out}' (status ${rc}): ${err}")
endif()
if(NOT EXISTS ${prefix}/lib/seamless-step-iges AND NOT EXISTS ${prefix}/lib64/seamless-step-iges)
  message(FATAL_ERROR "the STEP/IGES reader is not installed beside the library")
endif()
message(STATUS "the installed STEP/IGES reader read torus.igs: ${out} patches")
