# Builds the uniform tables with g++ and with clang++, dumps the bytes of both table objects and compares
# them (the issue: "the bytes are identical from g++ and clang"); the project builds with both (README).
# cmake -DSRC=<repository root> -DWORK=<scratch dir> -P this
find_program(GXX g++)
find_program(CLANGXX clang++)
if(NOT GXX OR NOT CLANGXX)
  message(FATAL_ERROR "the comparison needs both g++ and clang++ on PATH")
endif()
file(MAKE_DIRECTORY ${WORK})
set(common -std=c++20 -O1 -I${SRC}/constexpr -I${SRC}/runtime/include -I${SRC}/runtime/src)
set(sources ${SRC}/runtime/src/uniform/tables_11.cpp ${SRC}/runtime/src/uniform/tables_16.cpp
            ${SRC}/tests/uniform/dump_uniform_tables.cpp)
execute_process(COMMAND ${GXX} ${common} -fconstexpr-ops-limit=4294967296 -fconstexpr-loop-limit=4194304
                        ${sources} -o ${WORK}/dump_gxx RESULT_VARIABLE rc1)
execute_process(COMMAND ${CLANGXX} ${common} -fconstexpr-steps=2147483647 ${sources} -o ${WORK}/dump_clang
                RESULT_VARIABLE rc2)
if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0)
  message(FATAL_ERROR "building the table dump failed (g++ ${rc1}, clang++ ${rc2})")
endif()
execute_process(COMMAND ${WORK}/dump_gxx OUTPUT_FILE ${WORK}/tables_gxx.bin RESULT_VARIABLE rc1)
execute_process(COMMAND ${WORK}/dump_clang OUTPUT_FILE ${WORK}/tables_clang.bin RESULT_VARIABLE rc2)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/tables_gxx.bin ${WORK}/tables_clang.bin
                RESULT_VARIABLE diff)
file(SIZE ${WORK}/tables_gxx.bin bytes)
if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0 OR NOT diff EQUAL 0 OR bytes EQUAL 0)
  message(FATAL_ERROR "the uniform tables differ between g++ and clang++ (or a dump failed)")
endif()
message(STATUS "uniform tables: ${bytes} bytes, identical from g++ and clang++")
