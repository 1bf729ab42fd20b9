# Builds and runs the consumer project (CONSUMER_SOURCE_DIR) against deformseg in one of the three
# ways chapter 1 describes, in WORK_DIR:
#   ROUTE=installed       cmake --install of the project built in BINARY_DIR into a prefix, then
#                         find_package with CMAKE_PREFIX_PATH;
#   ROUTE=build_tree      a build tree of SOURCE_DIR configured as a library user would (tests,
#                         examples off, and none of their dependencies found: CLI11, nlohmann-json,
#                         Catch2, Doxygen), then find_package with deformseg_DIR;
#   ROUTE=add_subdirectory the sources added to the consumer's own build.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${output}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

set(consumer_options -DCMAKE_BUILD_TYPE=Release)
if(ROUTE STREQUAL "installed")
  run(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix)
  list(APPEND consumer_options -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
elseif(ROUTE STREQUAL "build_tree")
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/deformseg -DCMAKE_BUILD_TYPE=Release
      -DDEFORMSEG_BUILD_TESTS=OFF -DDEFORMSEG_BUILD_EXAMPLES=OFF
      -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON
      -DCMAKE_DISABLE_FIND_PACKAGE_Catch2=ON -DCMAKE_DISABLE_FIND_PACKAGE_Doxygen=ON)
  # The library alone builds nothing: no precompiled header, no program.
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/deformseg --target help)
  if(output MATCHES "deformseg_pch|deformseg_tool|deformseg_tests")
    message(FATAL_ERROR "a build of the library alone has targets of the project's programs:\n${output}")
  endif()
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/deformseg)
  list(APPEND consumer_options -Ddeformseg_DIR=${WORK_DIR}/deformseg)
elseif(ROUTE STREQUAL "add_subdirectory")
  list(APPEND consumer_options -DDEFORMSEG_SOURCE_DIR=${SOURCE_DIR})
else()
  message(FATAL_ERROR "ROUTE is installed, build_tree or add_subdirectory, not '${ROUTE}'")
endif()
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build ${consumer_options})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
