# Regenerates the uniform-density pattern data and compares it byte for byte with the checked-in file.
# cmake -DGEN=ctess_uniform_gen -DOUT=file -DEXPECT=constexpr/ctess/uniform/patterns_data.hpp -P this
execute_process(COMMAND ${GEN} --max 16 --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "uniform_gen failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${EXPECT} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "the regenerated ${OUT} differs from ${EXPECT}: regenerate (gen/uniform_patterns/README.md)")
endif()
message(STATUS "uniform_gen: the regenerated data equals ${EXPECT}")
