cmake_minimum_required(VERSION 3.25) # the policies of the project (CMP0007: list() keeps empty lines)
# Runs the Cortex-M4 image under QEMU and the host build of the same program (size_report/m4_run.cpp), and
# fails unless both exit 0, both report "result: pass", and their outputs are equal byte for byte once the
# informational lines (starting with '#': stack and instruction figures, target only) are removed.
# -icount shift=0: virtual time advances 1 ns per instruction, which makes SysTick count instructions.
foreach(var QEMU ELF HOST)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compare_m4_run.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND ${HOST} RESULT_VARIABLE host_rc OUTPUT_VARIABLE host_out ERROR_VARIABLE host_err
                TIMEOUT 20)
execute_process(COMMAND ${QEMU} -M mps2-an386 -nographic -monitor none -serial none
                        -semihosting-config enable=on,target=native -icount shift=0 -kernel ${ELF}
                RESULT_VARIABLE target_rc OUTPUT_VARIABLE target_out ERROR_VARIABLE target_err TIMEOUT 25)

# The informational lines are shown (ctest -V), then dropped: a newline is put in front of each output so that
# every line, the first included, is "\n" + its text, and "\n#..." removes exactly one line.
message("${target_out}")
string(REGEX REPLACE "\n#[^\n]*" "" target_cmp "\n${target_out}")
string(REGEX REPLACE "\n#[^\n]*" "" host_cmp "\n${host_out}")

# -DCORRUPT_HOST=ON: one digest digit of the host's output is changed, for the test that the comparison can
# fail (tests/embedded/CMakeLists.txt).
if(CORRUPT_HOST)
  string(FIND "${host_cmp}" " vd=" at)
  math(EXPR at "${at} + 4")
  string(SUBSTRING "${host_cmp}" 0 ${at} head)
  math(EXPR rest "${at} + 1")
  string(SUBSTRING "${host_cmp}" ${rest} -1 tail)
  set(host_cmp "${head}X${tail}")
endif()

set(failed "")
if(NOT host_rc STREQUAL "0")
  string(APPEND failed "host program exit status ${host_rc} ${host_err}\n")
endif()
if(NOT target_rc STREQUAL "0")
  string(APPEND failed "QEMU exit status ${target_rc} (the image's main returns 1 on a failure) ${target_err}\n")
endif()
if(NOT host_cmp MATCHES "\nresult: pass\n$")
  string(APPEND failed "the host output does not end with 'result: pass'\n")
endif()
if(NOT target_cmp STREQUAL host_cmp)
  string(REPLACE "\n" ";" host_lines "${host_cmp}")
  string(REPLACE "\n" ";" target_lines "${target_cmp}")
  list(LENGTH host_lines host_n)
  list(LENGTH target_lines target_n)
  string(APPEND failed "outputs differ: ${host_n} host lines, ${target_n} target lines\n")
  math(EXPR last "${host_n} - 1")
  foreach(k RANGE ${last})
    list(GET host_lines ${k} h)
    set(t "<missing>")
    if(k LESS target_n)
      list(GET target_lines ${k} t)
    endif()
    if(NOT h STREQUAL t)
      string(APPEND failed "first difference, line ${k}:\n  host:   ${h}\n  target: ${t}\n")
      break()
    endif()
  endforeach()
endif()
if(failed)
  message(FATAL_ERROR "${failed}")
endif()
string(REGEX MATCHALL "\n[a-z]+ [a-z]+ [0-9]+ f=" cases "${host_cmp}")
list(LENGTH cases case_lines)
message("equal: ${case_lines} case lines, verify_tables and the result, bit for bit")
