# SPDX-License-Identifier: MIT
# Fails when a header of lib/ includes a third-party mesh library (OpenMesh,
# CGAL) other than the opt-in conversion headers whose whole point is that
# library's type (mesh/openmesh.h, mesh/surface_mesh.h), when any other file
# of lib/ includes those two (a user opts in by including them; libseamless
# itself must not depend on them), or when a .cpp of lib/ includes OpenMesh
# (the library does not link it).
cmake_policy(SET CMP0057 NEW)
file(GLOB_RECURSE _files ${LIB_DIR}/*.h ${LIB_DIR}/*.cpp)
set(_conversions ${LIB_DIR}/mesh/openmesh.h ${LIB_DIR}/mesh/surface_mesh.h)
set(_bad "")
foreach(f IN LISTS _files)
  if(f IN_LIST _conversions)
    continue()
  endif()
  file(STRINGS ${f} _lines REGEX "^[ \t]*#[ \t]*include[ \t]*<(seamless/mesh/(openmesh|surface_mesh)\\.h|OpenMesh/)")
  if(f MATCHES "\\.h$")
    file(STRINGS ${f} _cgal REGEX "^[ \t]*#[ \t]*include[ \t]*<CGAL/")
    list(APPEND _lines ${_cgal})
  endif()
  if(_lines)
    list(APPEND _bad "${f}: ${_lines}")
  endif()
endforeach()
foreach(f IN LISTS _conversions)
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "${f} is missing: wrong folder?")
  endif()
endforeach()
if(_bad)
  string(REPLACE ";" "\n" _bad "${_bad}")
  message(FATAL_ERROR "third-party mesh libraries outside the conversion headers:\n${_bad}")
endif()
message(STATUS "OpenMesh and CGAL headers only in mesh/openmesh.h and mesh/surface_mesh.h")
