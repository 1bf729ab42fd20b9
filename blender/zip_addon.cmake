# Zips the Blender add-on (blender/deformseg_blender) into OUT, the zip that Blender's Edit >
# Preferences > Add-ons > Install takes. The target blender_addon runs it (build/blender/
# deformseg_blender.zip), and so does the test blender_addon, which installs the zip it makes.
# Usage: cmake -DOUT=deformseg_blender.zip -P blender/zip_addon.cmake
if(NOT OUT)
  message(FATAL_ERROR "usage: cmake -DOUT=deformseg_blender.zip -P zip_addon.cmake")
endif()
get_filename_component(here "${CMAKE_CURRENT_LIST_FILE}" DIRECTORY)
# The Python files only: no __pycache__ of a development session.
file(GLOB sources RELATIVE "${here}" "${here}/deformseg_blender/*.py")
get_filename_component(out_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")
file(REMOVE "${OUT}")
execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf "${OUT}" --format=zip ${sources}
                WORKING_DIRECTORY "${here}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "could not write ${OUT}")
endif()
