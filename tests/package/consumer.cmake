# ctest: configures, builds and runs examples/consumer against the singlestrip installed in PREFIX,
# with nothing but CMAKE_PREFIX_PATH (find_package must find every dependency itself).
#   cmake -DPREFIX=<install> -DSOURCE=<examples/consumer> -DBUILD=<dir> -DGENERATOR=<gen> -P consumer.cmake
file(REMOVE_RECURSE ${BUILD})
foreach(step
    "${CMAKE_COMMAND};-S;${SOURCE};-B;${BUILD};-G;${GENERATOR};-DCMAKE_BUILD_TYPE=Release;-DCMAKE_PREFIX_PATH=${PREFIX}"
    "${CMAKE_COMMAND};--build;${BUILD}"
    "${BUILD}/consumer")
  execute_process(COMMAND ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${step} failed (${rc}):\n${out}\n${err}")
  endif()
endforeach()
