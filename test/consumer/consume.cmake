# Builds and runs the consumer project (CONSUMER_SOURCE_DIR) against deformseg in one of the three
# ways chapter 1 describes, in WORK_DIR, once linking the algorithms (deformseg::deformseg) and
# once the readers (deformseg::io):
#   ROUTE=installed       cmake --install of the project built in BINARY_DIR into a prefix, then
#                         find_package with CMAKE_PREFIX_PATH;
#   ROUTE=build_tree      a build tree of SOURCE_DIR configured as a library user would (tests,
#                         examples off, and none of their dependencies found: nlohmann-json,
#                         CLI11, Catch2, Doxygen), then find_package with deformseg_DIR; without
#                         nlohmann-json, deformseg::io reads no glTF;
#   ROUTE=add_subdirectory the sources added to the consumer's own build.
# The algorithms' consumer must not link TinyGLTF, and by find_package it is configured with
# TinyGLTF hidden: the package must not look for it. The readers' consumer reads GLTF_FILE: the
# animation when HAS_GLTF (deformseg found TinyGLTF), the refusal that names tinygltf otherwise.
file(REMOVE_RECURSE ${WORK_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)

# The consumers unoptimised (no build type): they run in no time, and most of the test's time is
# their compilation, a third shorter at -O0. So is the build tree's library (ROUTE=build_tree), which
# the add_subdirectory route compiles unoptimised too.
set(consumer_options "")
set(hide_tinygltf -DCMAKE_DISABLE_FIND_PACKAGE_TinyGLTF=ON)
if(ROUTE STREQUAL "installed")
  run(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix)
  list(APPEND consumer_options -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
elseif(ROUTE STREQUAL "build_tree")
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/deformseg
      -DDEFORMSEG_BUILD_TESTS=OFF -DDEFORMSEG_BUILD_EXAMPLES=OFF
      -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
      -DCMAKE_DISABLE_FIND_PACKAGE_Catch2=ON -DCMAKE_DISABLE_FIND_PACKAGE_Doxygen=ON)
  # The library alone builds nothing: no precompiled header, no program.
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/deformseg --target help)
  if(output MATCHES "deformseg_pch|deformseg_tool|deformseg_tests")
    message(FATAL_ERROR "a build of the library alone has targets of the project's programs:\n${output}")
  endif()
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/deformseg)
  list(APPEND consumer_options -Ddeformseg_DIR=${WORK_DIR}/deformseg -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON)
  set(HAS_GLTF OFF)
  set(HAS_ASSIMP OFF)  # Assimp is read only with tinygltf
elseif(ROUTE STREQUAL "add_subdirectory")
  list(APPEND consumer_options -DDEFORMSEG_SOURCE_DIR=${SOURCE_DIR})
  set(hide_tinygltf "")  # deformseg's own CMakeLists looks for it, for deformseg::io
else()
  message(FATAL_ERROR "ROUTE is installed, build_tree or add_subdirectory, not '${ROUTE}'")
endif()

# Configures and builds the consumer of deformseg::${target} in WORK_DIR/consumer_${target};
# `output` is the build's, with every command line.
function(build_consumer target)
  set(build ${WORK_DIR}/consumer_${target})
  run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${build} -DCONSUMER_TARGET=${target} ${consumer_options} ${ARGN})
  # The consumer alone, not `all`: added as a subdirectory, deformseg's own targets are in `all`, and
  # the readers' library would be compiled for the algorithms' consumer too, which does not link it.
  run(${CMAKE_COMMAND} --build ${build} --target consumer --verbose)
  set(output "${output}" PARENT_SCOPE)
endfunction()

build_consumer(deformseg ${hide_tinygltf})
string(TOLOWER "${output}" build_commands)
if(build_commands MATCHES "tinygltf")
  message(FATAL_ERROR "the consumer of deformseg::deformseg is built with tinygltf:\n${output}")
endif()
run(${WORK_DIR}/consumer_deformseg/consumer)

build_consumer(io)
string(TOLOWER "${output}" build_commands)
if(HAS_GLTF AND NOT build_commands MATCHES "tinygltf")
  message(FATAL_ERROR "the consumer of deformseg::io is built without tinygltf:\n${output}")
endif()
execute_process(COMMAND ${WORK_DIR}/consumer_io/consumer ${GLTF_FILE} RESULT_VARIABLE status OUTPUT_VARIABLE output)
if(HAS_GLTF)
  set(expected "^read 1 frames of 1 triangles\n$")
else()
  set(expected "^error: .*built without tinygltf")
endif()
if(NOT output MATCHES "${expected}")
  message(FATAL_ERROR "the consumer of deformseg::io read ${GLTF_FILE} (status ${status}):\n${output}\n"
                      "expected: ${expected}")
endif()
# With Assimp, the readers' consumer reads BVH_FILE. Unless deformseg::io links Assimp (ASSIMP_LINKED:
# its target gave no soname), it opens Assimp's library on the first FBX, Collada or BVH read
# (src/io/assimp_import.cpp): the consumer starts without it (glibc's LD_DEBUG=files lists what the
# loader opens), and the package looked for no Assimp.
if(HAS_ASSIMP AND NOT ASSIMP_LINKED)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${WORK_DIR}/consumer_io/consumer ${GLTF_FILE}
                  OUTPUT_QUIET ERROR_VARIABLE loaded)
  if(NOT loaded MATCHES "file=" OR loaded MATCHES "file=[^ ]*libassimp")
    message(FATAL_ERROR "the consumer of deformseg::io loaded Assimp, or LD_DEBUG listed nothing, at a glTF read:\n"
                        "${loaded}")
  endif()
endif()
if(HAS_ASSIMP)
  execute_process(COMMAND ${WORK_DIR}/consumer_io/consumer ${BVH_FILE} RESULT_VARIABLE status OUTPUT_VARIABLE output)
  if(NOT output MATCHES "^read [1-9][0-9]* frames of [1-9][0-9]* triangles\n$")
    message(FATAL_ERROR "the consumer of deformseg::io read ${BVH_FILE} (status ${status}):\n${output}")
  endif()
endif()
