# The Blender test matrix: every Blender-side suite runs once per Blender the project supports —
# Debian's `blender` binary (3.4 here) and each `bpy` wheel (4.2, 4.5, 5.0 on CPython 3.11; 5.2 on
# the CPython 3.13 of scripts/env/python313.sh), each in its own virtual environment made by
# scripts/env/blender_envs.sh. scripts/test.sh passes them as
#   -DHBC_BPY_PYTHONS="4.2=/path/bin/python;4.5=...;5.2=..."
# Each test is named <suite>@blender-<version> or <suite>@bpy-<version>, with its own user folders.
#
# A Blender the build is configured for must be there and run: each has a first test,
# blender_check@<label> (tests/blender_check.cmake), that fails naming what is missing, and its
# suites need it (a ctest fixture), so a missing Blender fails the run instead of leaving its suites
# out. Debian's blender is expected unless the build is configured with -DHBC_BLENDER=OFF (then,
# with no HBC_BPY_PYTHONS either, there is no Blender suite, and configuring says so).

option(HBC_BLENDER "Run the Blender-side suites in Debian's blender (BLENDER_EXECUTABLE); OFF leaves it out" ON)
set(HBC_BPY_PYTHONS "" CACHE STRING "version=python pairs of the bpy wheels' virtual environments")

set(HBC_BLENDER_RUNS "")  # label=executable, one per Blender of the matrix
if(HBC_SANITIZE OR HBC_TSAN)
  # No Blender loads an instrumented module: a sanitizer tree has no Blender suite.
elseif(HBC_BLENDER)
  find_program(BLENDER_EXECUTABLE blender)
  set(version "")
  if(BLENDER_EXECUTABLE)
    execute_process(COMMAND ${BLENDER_EXECUTABLE} --version OUTPUT_VARIABLE out ERROR_QUIET
                    RESULT_VARIABLE rc TIMEOUT 60)
    if(rc EQUAL 0 AND out MATCHES "Blender ([0-9]+\\.[0-9]+)")
      set(version ${CMAKE_MATCH_1})
    endif()
  endif()
  if(version)
    list(APPEND HBC_BLENDER_RUNS "blender-${version}=${BLENDER_EXECUTABLE}")
  else()
    # Registered anyway: its check fails at test time with the reason.
    message(WARNING "Debian's blender (${BLENDER_EXECUTABLE}) is missing or does not run: its suites will fail. "
                    "Install it (scripts/env/deps.sh) or configure with -DHBC_BLENDER=OFF.")
    list(APPEND HBC_BLENDER_RUNS "blender=${BLENDER_EXECUTABLE}")
  endif()
endif()
if(NOT (HBC_SANITIZE OR HBC_TSAN))
  foreach(pair ${HBC_BPY_PYTHONS})
    list(APPEND HBC_BLENDER_RUNS "bpy-${pair}")
  endforeach()
  if(NOT HBC_BLENDER_RUNS)
    message(STATUS "Blender suites: none (HBC_BLENDER=OFF and no HBC_BPY_PYTHONS)")
  endif()
endif()

# One check per Blender: it starts, is the version the build expects, and runs pytest through
# tests/run_pytest_in_blender.py, whose exit status is pytest's: over a folder that holds no
# test it must be 5 ("no tests collected"), so a suite that finds nothing fails.
set(HBC_BLENDER_CHECK_DIR ${CMAKE_BINARY_DIR}/blender_check)
file(WRITE ${HBC_BLENDER_CHECK_DIR}/conftest.py
     "import bpy\nprint('blender_check: Blender', bpy.app.version_string, flush=True)\n")
foreach(run ${HBC_BLENDER_RUNS})
  string(REGEX MATCH "^[^=]+" label "${run}")
  string(REGEX REPLACE "^[^=]+=" "" exe "${run}")
  string(REGEX REPLACE "^(blender|bpy)-?" "" version "${label}")
  add_test(NAME blender_check@${label}
    COMMAND ${CMAKE_COMMAND} -DLABEL=${label} -DEXE=${exe} -DVERSION=${version}
            -DRUNNER=${CMAKE_SOURCE_DIR}/tests/run_pytest_in_blender.py -DEMPTY=${HBC_BLENDER_CHECK_DIR}
            -P ${CMAKE_SOURCE_DIR}/tests/blender_check.cmake)
  set(home ${CMAKE_BINARY_DIR}/blender_user/${label}/check)
  set_tests_properties(blender_check@${label} PROPERTIES
    ENVIRONMENT "BLENDER_USER_CONFIG=${home}/config;BLENDER_USER_SCRIPTS=${home}/scripts;PYTHONDONTWRITEBYTECODE=1"
    FIXTURES_SETUP blender-${label} TIMEOUT 120 LABELS "blender;${label}")
endforeach()

# hbc_blender_test(SUITE NAME [ENDS] ARGS pytest-args... ENV env-entries... TIMEOUT seconds)
# ENDS: only in the first and the last Blender of the matrix (Debian's 3.4 and the newest wheel, as
# scripts/test.sh lists them oldest first): for slow suites that the time budget keeps off the middle.
function(hbc_blender_test)
  cmake_parse_arguments(T "ENDS" "SUITE;TIMEOUT" "ARGS;ENV" ${ARGN})
  set(runs ${HBC_BLENDER_RUNS})
  list(LENGTH runs n)
  if(T_ENDS AND n GREATER 2)
    list(GET runs 0 first)
    list(GET runs -1 last)
    set(runs ${first} ${last})
  endif()
  foreach(run ${runs})
    string(REGEX MATCH "^[^=]+" label "${run}")
    string(REGEX REPLACE "^[^=]+=" "" exe "${run}")
    if(NOT exe)
      set(exe blender)  # not found: the check says so, and this suite is not run
    endif()
    set(home ${CMAKE_BINARY_DIR}/blender_user/${label}/${T_SUITE})
    if(label MATCHES "^blender")
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
      FIXTURES_REQUIRED blender-${label}
      COST 60  # before the quick tests (ctest -j starts the costliest first): no lone long tail
      TIMEOUT ${T_TIMEOUT}
      LABELS "blender;${label}")
  endforeach()
endfunction()
