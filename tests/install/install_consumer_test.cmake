# ctest: installs the built ergo into a fresh prefix, then configures, builds and runs
# tests/install/consumer against it with find_package(ergo CONFIG REQUIRED).
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P install_consumer_test.cmake
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "install_consumer_test.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed lib/cmake/ergo/ergoConfig.cmake include/ergo/mesh/tri_mesh.h bin/ergo_optimize
                  share/ergo/tools/plot_results.py)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "the install has no ${installed}")
  endif()
endforeach()
# The consumer must find ergo only through the installed package, never the build tree.
run_step("configure the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
         -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
         -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run_step("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build -j 2)
run_step("run the consumer" ${WORK_DIR}/build/ergo_consumer)
message(STATUS "${step_output}")
# The Python package, from where the install put it (the interpreter's site directory
# under the prefix), not from the build tree.
if(PYTHON AND PYTHON_DIR)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  run_step("import the installed Python package" ${PYTHON} -c
           "import ergo, os; assert os.path.realpath(ergo.__file__).startswith(os.path.realpath('${prefix}')), ergo.__file__; print(ergo.__file__, ergo.optimizers())")
  message(STATUS "${step_output}")
endif()
