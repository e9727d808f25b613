# ctest -R package_consumer: installs this build's core into a temp prefix,
# then configures, builds and runs examples/consumer against it, as another
# project would. Run with cmake -P and -DBUILD_DIR, -DSOURCE_DIR, -DWORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
foreach(f include/tumble/core/body.hpp lib/cmake/tumble/tumbleConfig.cmake lib/cmake/tumble/tumbleConfigVersion.cmake)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "install did not produce ${f}")
  endif()
endforeach()
run_step("configure example" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/build
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run_step("build example" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
# The example must have got the floating-point flag from tumble::core, not from us.
file(GLOB_RECURSE flags ${WORK_DIR}/build/*/flags.make)
file(READ "${flags}" flag_text)
if(NOT flag_text MATCHES "-ffp-contract=off")
  message(FATAL_ERROR "tumble::core did not pass -ffp-contract=off to its consumer:\n${flag_text}")
endif()
run_step("run example" ${WORK_DIR}/build/spin_box)
message("${step_output}")
foreach(line "mass 2 kg" "principal moments 2.5 5 6.5 kg m\\^2" "stepped 10000 steps to t = 10 s"
             "relative energy change [^\n]* \\(ok\\)" "relative change of L [^\n]* \\(ok\\)")
  if(NOT step_output MATCHES "${line}")
    message(FATAL_ERROR "example output lacks '${line}'")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
