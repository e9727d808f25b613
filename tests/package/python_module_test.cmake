# Fails when this test build left out the Python module although what it
# needs is installed (pybind11-dev, python3-dev): the README promises
# `import tumble` after scripts/test.sh, and a build folder first configured
# by the demo (tests off) once kept the module off without a word.
#   cmake -DBUILD_DIR=<build> -DPYTHON=<python3> -DMODULE_ON=<ON|OFF> -P python_module_test.cmake
foreach(v BUILD_DIR PYTHON MODULE_ON)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "${v} not set")
  endif()
endforeach()
# Asked here, not of the build's configure: pybind11's CMake package and Python.h.
find_file(PYBIND11_CONFIG pybind11Config.cmake PATHS /usr /usr/local
          PATH_SUFFIXES lib/cmake/pybind11 share/cmake/pybind11 NO_DEFAULT_PATH NO_CACHE)
set(PY_INCLUDE "")
if(EXISTS "${PYTHON}")
  execute_process(COMMAND "${PYTHON}" -c "import sysconfig; print(sysconfig.get_paths()['include'])"
                  OUTPUT_VARIABLE PY_INCLUDE OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
endif()
if(NOT PYBIND11_CONFIG OR NOT EXISTS "${PY_INCLUDE}/Python.h")
  message(STATUS "pybind11 or Python.h not installed (${PYBIND11_CONFIG}, ${PY_INCLUDE}): no module expected")
  return()
endif()
if(NOT MODULE_ON)
  message(FATAL_ERROR "pybind11 (${PYBIND11_CONFIG}) and Python.h are installed, yet this test build has no Python "
                      "module (TUMBLE_BUILD_PYTHON resolved to OFF): configure with -DTUMBLE_BUILD_PYTHON=AUTO, or run scripts/test.sh")
endif()
file(GLOB modules "${BUILD_DIR}/python/tumble/_tumble*.so")
if(NOT modules)
  message(FATAL_ERROR "no ${BUILD_DIR}/python/tumble/_tumble*.so: the module is configured but not built")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${BUILD_DIR}/python" "${PYTHON}" -c "import tumble; print(tumble.__file__)"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import tumble failed (${rc}): ${err}")
endif()
message(STATUS "python module: ${modules}, imports as ${out}")
