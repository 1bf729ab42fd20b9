# The Blender add-on (blender/deformseg_blender), headless: zipped as the target blender_addon zips
# it, installed into a scratch user folder by Blender's own add-on installer, and tested on the
# shared Fox by test_addon.py against the deformseg module on the same clip; then, as a new user
# sets it up, found through its preference (test_preference.py). Skipped, saying why,
# where Blender, the Python module or the Fox is missing.
# Arguments: -DSOURCE= the repository, -DMODULE_DIR= the folder holding the deformseg package (a
# build's python/), -DDATA= the shared data, -DOUT= a scratch folder, -DTOOL= the deformseg tool
# (optional: its outputs are compared too). DEFORMSEG_BLENDER names another Blender.
include(${CMAKE_CURRENT_LIST_DIR}/../find_blender.cmake)
find_blender_or_skip()
file(GLOB module_files "${MODULE_DIR}/deformseg/_deformseg*.so")
if(NOT module_files)
  message("SKIPPED: no deformseg Python module in ${MODULE_DIR} (configure with -DDEFORMSEG_BUILD_PYTHON=ON and "
          "build _deformseg, or give -DDEFORMSEG_BLENDER_MODULE_DIR=BUILD/python)")
  return()
endif()
if(NOT EXISTS "${DATA}/characters/Fox.glb")
  message("SKIPPED: no shared glTF character Fox.glb in ${DATA}/characters")
  return()
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND ${CMAKE_COMMAND} -DOUT=${OUT}/deformseg_blender.zip -P ${SOURCE}/blender/zip_addon.cmake
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "could not zip the add-on")
endif()
string(TIMESTAMP started "%s")
# --factory-startup: Blender's own settings; BLENDER_USER_SCRIPTS: the add-on is installed into the
# scratch folder, not the user's; --python-use-system-env: PYTHONPATH reaches Blender's Python.
set(tool_variable "")
if(TOOL AND EXISTS "${TOOL}")
  set(tool_variable "DEFORMSEG_TOOL=${TOOL}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${MODULE_DIR}" PYTHONDONTWRITEBYTECODE=1 ${tool_variable}
                        "BLENDER_USER_SCRIPTS=${OUT}/scripts" "BLENDER_USER_CONFIG=${OUT}/config"
                        "${BLENDER}" -b --factory-startup --python-use-system-env --python-exit-code 1
                        --python ${SOURCE}/test/blender_addon/test_addon.py
                        -- ${OUT}/deformseg_blender.zip ${DATA}/characters/Fox.glb ${OUT} ${DATA}/characters/Knight.glb
                TIMEOUT 240 RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(result EQUAL 0)
  # A new user's set-up: no PYTHONPATH, the module found through the add-on's preference.
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONPATH PYTHONDONTWRITEBYTECODE=1
                          "BLENDER_USER_SCRIPTS=${OUT}/scripts-preference" "BLENDER_USER_CONFIG=${OUT}/config-preference"
                          "${BLENDER}" -b --factory-startup --python-exit-code 1
                          --python ${SOURCE}/test/blender_addon/test_preference.py
                          -- ${OUT}/deformseg_blender.zip ${MODULE_DIR}
                  TIMEOUT 120 RESULT_VARIABLE result OUTPUT_VARIABLE preference_output ERROR_VARIABLE preference_output)
  string(APPEND output "${preference_output}")
endif()
string(TIMESTAMP finished "%s")
math(EXPR seconds "${finished} - ${started}")
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the Blender add-on's test failed (${result}) after ${seconds} s")
endif()
message("the Blender add-on's test passed in ${seconds} s")
