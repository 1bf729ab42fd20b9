# Builds the consumer project (CONSUMER_SOURCE_DIR) of default_types.cpp twice against the build tree
# BINARY_DIR as the package, in WORK_DIR, with the build type BUILD_TYPE (the library's, so that both
# builds compile the same code with the same flags): header-only (deformseg::deformseg) and linking
# deformseg::compiled. Checks that the second compiled the entry points against declarations (NM
# lists them undefined in its object file, and defines none of them), then that the two
# programs print the same results to the last bit. Skipped, saying why, when BINARY_DIR was
# configured without DEFORMSEG_BUILD_COMPILED (HAS_COMPILED).
if(NOT HAS_COMPILED)
  message("SKIPPED: this build has no deformseg::compiled (configure it with -DDEFORMSEG_BUILD_COMPILED=ON)")
  return()
endif()
file(REMOVE_RECURSE ${WORK_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)

# The entry points deformseg::compiled holds, as nm -C names them.
set(entry_points "strain::compute_strain<float," "strain::compute_strain<double,"
    "temporal::temporal_segmentation<deformseg::mesh::" "similarity::motion_similarity<"
    "similarity::similarity_matrix<" "spatiotemporal::spatiotemporal_segmentation<deformseg::mesh::"
    "spatiotemporal::evolving_graph<deformseg::mesh::" "mesh::make_bending_tube<")

# Builds the consumer linking deformseg::`target` in WORK_DIR/`target`; `symbols` is nm -C of its
# object file and `printed` what the program prints.
function(build_and_run target)
  set(build ${WORK_DIR}/${target})
  run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${build} -DCONSUMER_TARGET=${target}
      -DCONSUMER_SOURCE=default_types.cpp -Ddeformseg_DIR=${BINARY_DIR} -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
  run(${CMAKE_COMMAND} --build ${build})
  run(${NM} -C ${build}/CMakeFiles/consumer.dir/default_types.cpp.o)
  set(symbols "${output}" PARENT_SCOPE)
  run(${build}/consumer)
  set(printed "${output}" PARENT_SCOPE)
endfunction()

build_and_run(deformseg)
set(header_only_printed "${printed}")

build_and_run(compiled)
foreach(entry IN LISTS entry_points)
  string(REGEX MATCH "\n +U [^\n]*${entry}" declared "\n${symbols}")
  string(REGEX MATCH "\n[0-9a-f]+ [TW] [^\n]*${entry}" defined "\n${symbols}")
  if(NOT declared OR defined)
    message(FATAL_ERROR "the consumer of deformseg::compiled compiled ${entry}... itself:\n${defined}")
  endif()
endforeach()
if(NOT printed STREQUAL header_only_printed)
  file(WRITE ${WORK_DIR}/header_only.txt "${header_only_printed}")
  file(WRITE ${WORK_DIR}/compiled.txt "${printed}")
  message(FATAL_ERROR "the consumer of deformseg::compiled printed other results than the header-only one: "
                      "see ${WORK_DIR}/header_only.txt and ${WORK_DIR}/compiled.txt")
endif()
message("the same results, header-only and with deformseg::compiled")
