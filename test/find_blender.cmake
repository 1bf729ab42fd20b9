# Included by the scripts of the tests that run Blender headless (blender_fbx.cmake,
# blender_addon/run.cmake): find_blender_or_skip() sets BLENDER to Debian's Blender, or to the one
# DEFORMSEG_BLENDER names, or says the test is skipped and returns from the script that calls it
# (a macro: its return() is the caller's).
macro(find_blender_or_skip)
  if(DEFINED ENV{DEFORMSEG_BLENDER})
    set(BLENDER "$ENV{DEFORMSEG_BLENDER}")
  else()
    find_program(BLENDER blender)
  endif()
  if(NOT BLENDER OR NOT EXISTS "${BLENDER}")
    message("SKIPPED: Blender not found (Debian's package blender; DEFORMSEG_BLENDER names another)")
    return()
  endif()
endmacro()
