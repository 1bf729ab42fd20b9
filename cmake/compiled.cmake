# ---- deformseg::compiled: the algorithms compiled once for the default types (optional) --------
# As libigl's static library: the entry points on the default animation (mesh::Surface_mesh_animation)
# with their default policies, explicitly instantiated in src/compiled/ (one file per module). The
# target defines DEFORMSEG_COMPILED=1 for its consumers, under which the algorithms' headers declare
# those instantiations `extern template` (at the end of each header), so that a program on the
# default types compiles against declarations and links the code compiled here. Every definition
# stays in the headers: any other type or policy instantiates in the consumer's unit as before, and
# a consumer that does not link the target sees no change. Off by default, since it compiles code
# (a few CPU-minutes) where the header-only library compiles nothing.
option(DEFORMSEG_BUILD_COMPILED
       "Build deformseg::compiled, the algorithms instantiated for the default types (find_package COMPONENTS compiled)"
       OFF)
if(DEFORMSEG_BUILD_COMPILED)
  add_library(deformseg_compiled STATIC
    ${CMAKE_CURRENT_SOURCE_DIR}/src/compiled/mesh.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/src/compiled/strain.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/src/compiled/temporal.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/src/compiled/similarity.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/src/compiled/spatiotemporal.cpp)
  add_library(deformseg::compiled ALIAS deformseg_compiled)
  # Position independent, so that a shared library (a Python module, a plug-in) may link it too.
  set_target_properties(deformseg_compiled PROPERTIES EXPORT_NAME compiled POSITION_INDEPENDENT_CODE ON)
  target_link_libraries(deformseg_compiled PUBLIC deformseg)
  target_compile_definitions(deformseg_compiled PUBLIC DEFORMSEG_COMPILED=1)
  # The project's warnings, but not its -march: the code here must be the code a consumer's own
  # compile of the headers makes (the same flags give the same results to the last bit).
  if(PROJECT_IS_TOP_LEVEL)
    target_compile_options(deformseg_compiled PRIVATE -Wall -Wextra -Wpedantic
                           $<$<BOOL:${DEFORMSEG_WARNINGS_AS_ERRORS}>:-Werror>)
  endif()
  install(TARGETS deformseg_compiled EXPORT deformsegCompiledTargets)
  install(EXPORT deformsegCompiledTargets NAMESPACE deformseg:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/deformseg)
  export(EXPORT deformsegCompiledTargets NAMESPACE deformseg::
         FILE ${CMAKE_CURRENT_BINARY_DIR}/deformsegCompiledTargets.cmake)
  set(DEFORMSEG_HAS_COMPILED ON)  # for the package config
else()
  set(DEFORMSEG_HAS_COMPILED OFF)
endif()
