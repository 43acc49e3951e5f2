# blender_check@<label> (tests/blender_matrix.cmake): that a Blender of the matrix is there, is the
# version the build was configured for, and runs pytest with pytest's exit status. Run as
#   cmake -DLABEL=blender-3.4|bpy-4.2 -DEXE=<blender or the venv's python> -DVERSION=<major.minor>
#         -DRUNNER=<tests/run_pytest_in_blender.py> -DEMPTY=<a folder with no test> -P blender_check.cmake
# EMPTY holds only a conftest.py printing Blender's version: pytest collects nothing there and must
# exit 5, which the suites' runner passes on, so an empty suite fails like any other.
if(LABEL MATCHES "^blender")
  set(what "Debian's blender")
  set(hint "install it (scripts/env/deps.sh), or configure with -DHBC_BLENDER=OFF to run no suite in it")
  set(cmd ${EXE} -b --factory-startup --python-exit-code 1 --python ${RUNNER} -- -q -p no:cacheprovider ${EMPTY})
else()
  set(what "the bpy ${VERSION} environment")
  set(hint "make it with: bash scripts/env/blender_envs.sh ${VERSION} (or configure without it in HBC_BPY_PYTHONS)")
  set(cmd ${EXE} ${RUNNER} -q -p no:cacheprovider ${EMPTY})
endif()
if(NOT EXE OR NOT EXISTS "${EXE}")
  message(FATAL_ERROR "${what} is missing (${EXE}): ${hint}")
endif()
execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 100)
if(NOT out MATCHES "blender_check: Blender ([0-9]+\\.[0-9]+)")
  message(FATAL_ERROR "${what} (${EXE}) does not run pytest with bpy (exit status ${rc}): ${hint}\n"
                      "--- its output:\n${out}\n--- its errors:\n${err}")
endif()
set(found ${CMAKE_MATCH_1})
if(VERSION AND NOT found VERSION_EQUAL VERSION)
  message(FATAL_ERROR "${what} (${EXE}) is Blender ${found}, not ${VERSION}: reconfigure the build for it")
endif()
if(NOT rc EQUAL 5)
  message(FATAL_ERROR "${what} (${EXE}): pytest over a folder with no test exited with ${rc}, not 5 "
                      "(\"no tests collected\"): an empty suite would not fail.\n--- its output:\n${out}\n--- its errors:\n${err}")
endif()
message(STATUS "${what}: Blender ${found} (${EXE}) runs pytest, and an empty suite fails (exit status 5)")
