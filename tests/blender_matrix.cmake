# The Blender test matrix: every Blender-side suite runs once per Blender the project supports —
# Debian's `blender` binary (3.4 here) and each `bpy` wheel (4.2, 4.5, 5.0 on CPython 3.11; 5.2 on
# the CPython 3.13 of scripts/env/python313.sh), each in its own virtual environment made by
# scripts/env/blender_envs.sh. scripts/test.sh passes them as
#   -DHBC_BPY_PYTHONS="4.2=/path/bin/python;4.5=...;5.2=..."
# Each test is named <suite>@blender-<version> or <suite>@bpy-<version>, with its own user folders.

set(HBC_BPY_PYTHONS "" CACHE STRING "version=python pairs of the bpy wheels' virtual environments")
find_program(BLENDER_EXECUTABLE blender)
set(HBC_BLENDER_VERSION "")
if(BLENDER_EXECUTABLE)
  execute_process(COMMAND ${BLENDER_EXECUTABLE} --version OUTPUT_VARIABLE out ERROR_QUIET
                  RESULT_VARIABLE rc TIMEOUT 60)
  if(rc EQUAL 0 AND out MATCHES "Blender ([0-9]+\\.[0-9]+)")
    set(HBC_BLENDER_VERSION ${CMAKE_MATCH_1})
  else()
    set(BLENDER_EXECUTABLE "")
  endif()
endif()

# hbc_blender_test(SUITE NAME ARGS pytest-args... ENV env-entries... TIMEOUT seconds)
function(hbc_blender_test)
  cmake_parse_arguments(T "" "SUITE;TIMEOUT" "ARGS;ENV" ${ARGN})
  if(HBC_SANITIZE)
    return()  # Blender does not load an instrumented module
  endif()
  set(runs "")
  if(BLENDER_EXECUTABLE)
    list(APPEND runs "blender-${HBC_BLENDER_VERSION}=${BLENDER_EXECUTABLE}")
  endif()
  foreach(pair ${HBC_BPY_PYTHONS})
    list(APPEND runs "bpy-${pair}")
  endforeach()
  foreach(run ${runs})
    string(REGEX MATCH "^[^=]+" label "${run}")
    string(REGEX REPLACE "^[^=]+=" "" exe "${run}")
    set(home ${CMAKE_BINARY_DIR}/blender_user/${label}/${T_SUITE})
    if(label MATCHES "^blender-")
      # Debian's binary: pytest inside Blender's embedded Python, in background mode.
      set(cmd ${exe} -b --factory-startup --python-exit-code 1
              --python ${CMAKE_SOURCE_DIR}/tests/run_pytest_in_blender.py -- ${T_ARGS})
    else()
      # A bpy wheel: its venv's Python loads Blender (import bpy), then runs pytest.
      set(cmd ${exe} ${CMAKE_SOURCE_DIR}/tests/run_pytest_in_blender.py ${T_ARGS})
    endif()
    add_test(NAME ${T_SUITE}@${label} COMMAND ${cmd})
    set_tests_properties(${T_SUITE}@${label} PROPERTIES
      ENVIRONMENT "${T_ENV};BLENDER_USER_CONFIG=${home}/config;BLENDER_USER_SCRIPTS=${home}/scripts;BLENDER_USER_EXTENSIONS=${home}/extensions;PYTHONDONTWRITEBYTECODE=1"
      TIMEOUT ${T_TIMEOUT}
      LABELS "blender;${label}")
  endforeach()
endfunction()
