# SPDX-License-Identifier: MIT
# The library sources the fuzz harnesses' readers need, by room (a split
# inside a room is picked up; a reader that starts to need another room fails
# the test "fuzz: the stand-alone readers link", tests/CMakeLists.txt):
# base and its files room, the splines, the model readers, the mesh formats
# and the scene reader. No CGAL, TBB, tessellation or renderer. The STEP/IGES
# reader's own sources (OpenCASCADE) are SEAMLESS_STEP_IGES_SOURCES: they
# build its executable, which the readers run (lib/model/step_iges_loader.cpp).
set(_lib ${PROJECT_SOURCE_DIR}/lib)
file(GLOB SEAMLESS_READER_SOURCES CONFIGURE_DEPENDS
  ${_lib}/base/*.cpp ${_lib}/base/files/*.cpp ${_lib}/spline/*.cpp ${_lib}/model/*.cpp
  ${_lib}/mesh/io/*.cpp)
file(GLOB SEAMLESS_STEP_IGES_SOURCES CONFIGURE_DEPENDS ${_lib}/model/step_iges/*.cpp)
list(APPEND SEAMLESS_READER_SOURCES ${_lib}/render/scene/scene.cpp)
