# Configures, builds and runs one consumer project (ctest drives this script; see tests/CMakeLists.txt).
# -DSOURCE=<consumer dir> -DBINARY=<build dir> -DGENERATOR=... -DCXX=<compiler> [-DARGS=<one more cache arg>]
# [-DFLAGS=<CMAKE_CXX_FLAGS, e.g. the sanitizers of the build under test>]
# [-DPROGRAMS=<the programs to run, comma-separated; watertight_mesh when not given>]
file(REMOVE_RECURSE ${BINARY})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX}
                        -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS=${FLAGS}" ${ARGS} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring ${SOURCE} failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building ${SOURCE} failed")
endif()
if(NOT PROGRAMS)
  set(PROGRAMS watertight_mesh)
endif()
string(REPLACE "," ";" PROGRAMS "${PROGRAMS}")
foreach(program ${PROGRAMS})
  execute_process(COMMAND ${BINARY}/${program} WORKING_DIRECTORY ${BINARY} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the consumer's ${program} failed (${rc})")
  endif()
endforeach()
