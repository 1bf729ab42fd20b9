# The FBX reader against Autodesk's FBX SDK: converts the shared FBX characters with FBX2glTF
# (built on the SDK; scripts/fetch-fbx2gltf fetches it into the build tree), its keys baked at the
# files' own rate (24 fps), then runs the hidden test case [fbx-sdk] of the unit tests on both
# readings. Without FBX2glTF the test says why and CTest reports it skipped. Arguments: -DTESTS=
# the unit tests, -DDATA= the shared data, -DFBX2GLTF= the binary, -DOUT= a folder for the
# conversions.
if(DEFINED ENV{DEFORMSEG_FBX2GLTF})
  set(FBX2GLTF "$ENV{DEFORMSEG_FBX2GLTF}")
endif()
if(NOT EXISTS "${FBX2GLTF}")
  message("SKIPPED: FBX2glTF not found at ${FBX2GLTF} (scripts/fetch-fbx2gltf BUILD/fbx2gltf fetches it with "
          "the npm client; DEFORMSEG_FBX2GLTF names another)")
  return()
endif()
if(NOT EXISTS "${DATA}/fbx-collada")
  message("SKIPPED: no shared FBX characters in ${DATA}/fbx-collada")
  return()
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
foreach(name quat_man quat_woman)
  execute_process(COMMAND "${FBX2GLTF}" --binary --anim-framerate bake24 --input "${DATA}/fbx-collada/${name}.fbx"
                          --output "${OUT}/${name}"
                  TIMEOUT 120 RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0 OR NOT EXISTS "${OUT}/${name}.glb")
    message(FATAL_ERROR "FBX2glTF could not convert ${name}.fbx (${result}): ${output}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "DEFORMSEG_DATA_DIR=${DATA}" "DEFORMSEG_FBX_REFERENCES=${OUT}"
                        "${TESTS}" "[fbx-sdk]"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the FBX reader differs from the FBX SDK's reading")
endif()
