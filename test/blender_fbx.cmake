# The FBX reader on Blender's exports: Blender imports shared glTF characters and writes them as FBX
# with its own exporter (test/blender/export_fbx.py: the Fox at 24 fps, the Fox with its armature
# scaled by 1.3 and 0.8, the Knight at 30 fps, the robot, whose face has morph targets, at 24, the
# rates their keys are on), then the hidden test case [blender] of the unit tests compares every
# clip with the glTF file's. Without Blender (Debian's package blender; scripts/check installs it)
# the test says why and CTest reports it skipped. Blender's export changes some of the robot's clips
# (test/io_fbx_blender.cpp says which): when FBX2glTF, built on Autodesk's FBX SDK, was fetched
# (scripts/fetch-fbx2gltf BUILD/fbx2gltf), the robot's export is converted too, and the test
# compares every clip with the SDK's reading.
# Arguments: -DTESTS= the unit tests, -DDATA= the shared data, -DSCRIPT= export_fbx.py, -DOUT= a
# folder for the exports, -DFBX2GLTF= FBX2glTF (optional). DEFORMSEG_BLENDER names another Blender,
# DEFORMSEG_FBX2GLTF another FBX2glTF.
include(${CMAKE_CURRENT_LIST_DIR}/find_blender.cmake)
find_blender_or_skip()
if(NOT EXISTS "${DATA}/characters/Fox.glb" OR NOT EXISTS "${DATA}/characters/Knight.glb")
  message("SKIPPED: no shared glTF characters Fox.glb and Knight.glb in ${DATA}/characters")
  return()
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
set(characters "${DATA}/characters/Fox.glb@24" "${DATA}/characters/Fox.glb@24@1.3,0.8,1"
               "${DATA}/characters/Knight.glb@30" "${DATA}/characters/RobotExpressive.glb@24")
string(TIMESTAMP started "%s")
# Blender's own settings and add-ons (--factory-startup), Debian's Python modules (NumPy) for its
# glTF importer (--python-use-system-env).
execute_process(COMMAND "${BLENDER}" -b --factory-startup --python-use-system-env --python "${SCRIPT}" -- "${OUT}"
                        ${characters}
                TIMEOUT 300 RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
string(TIMESTAMP finished "%s")
math(EXPR seconds "${finished} - ${started}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "Blender could not export the characters (${result}): ${output}")
endif()
message("Blender exported the characters in ${seconds} s")
if(DEFINED ENV{DEFORMSEG_FBX2GLTF})
  set(FBX2GLTF "$ENV{DEFORMSEG_FBX2GLTF}")
elseif(NOT FBX2GLTF)
  get_filename_component(tests_dir "${TESTS}" DIRECTORY)
  find_program(FBX2GLTF FBX2glTF PATHS "${tests_dir}/fbx2gltf" "${tests_dir}/../fbx2gltf" NO_DEFAULT_PATH)
endif()
if(FBX2GLTF AND EXISTS "${FBX2GLTF}")
  execute_process(COMMAND "${FBX2GLTF}" --binary --anim-framerate bake24 --input "${OUT}/RobotExpressive.fbx"
                          --output "${OUT}/sdk/RobotExpressive"
                  TIMEOUT 120 RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0 OR NOT EXISTS "${OUT}/sdk/RobotExpressive.glb")
    message(FATAL_ERROR "FBX2glTF could not convert RobotExpressive.fbx (${result}): ${output}")
  endif()
  message("FBX2glTF converted the robot: its clips are compared with the FBX SDK's reading too")
else()
  message("FBX2glTF not found: the robot's clips that Blender changes are not compared")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "DEFORMSEG_DATA_DIR=${DATA}" "DEFORMSEG_BLENDER_EXPORTS=${OUT}"
                        "DEFORMSEG_BLENDER_SDK_READINGS=${OUT}/sdk" "${TESTS}" "[blender]"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the FBX reader's frames of Blender's exports differ from the glTF originals'")
endif()
