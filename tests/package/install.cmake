# ctest fixture: installs the build tree BUILD into a fresh PREFIX (cmake --install).
#   cmake -DBUILD=<build dir> -DPREFIX=<dir> -P install.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD} --prefix ${PREFIX} failed (${rc})")
endif()
message(STATUS "installed into ${PREFIX}")
