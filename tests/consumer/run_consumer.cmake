# SPDX-License-Identifier: MIT
# ctest driver: install the build tree into a scratch prefix, build the consumer
# project against it, run it on the teapot and expect 32 patches, and its
# OpenMesh round trip (the installed opt-in header) to give the mesh back.
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
