# What CTest checks of the heartbeat program (examples/heartbeat), in-tree (example-heartbeat)
# and built against the installed package (example-installed-package):
#   cmake -DPROGRAM=<heartbeat> -DWORK_DIR=<dir> -P check_heartbeat.cmake
# Each command of the program that cli::run gives it, with its exit code and what it
# prints: list (text and JSON), check (a holds, a violated with JUnit and HTML reports),
# explore, suite, and the one-line usage errors named after the program.

foreach(var PROGRAM WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "check_heartbeat.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# expect(<exit code> <regex on stdout and stderr> <argument>...)
function(expect code regex)
  list(JOIN ARGN " " command)
  execute_process(COMMAND ${PROGRAM} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
  if(NOT rc STREQUAL "${code}")
    message(FATAL_ERROR "heartbeat ${command}: exit ${rc}, expected ${code}\n${out}${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "heartbeat ${command}: no match for '${regex}' in\n${out}${err}")
  endif()
  message(STATUS "heartbeat ${command}: exit ${rc}, as expected")
endfunction()

expect(0 "heartbeat: a heartbeat failure detector.*no-false-suspicion.*stabilisation" list)
expect(0 "\"name\": \"heartbeat\".*\"name\": \"P\".*\"name\": \"stabilisation\"" list --json)
expect(0 "summary: 3 properties: 3 hold, 0 violated, 0 incomplete" check heartbeat --threads 1)
expect(0 "\"verdict\": \"holds\".*\"worst_time\": 3.*\"role\": \"witness\""
       check heartbeat --prop stabilisation --threads 1 --json)
expect(1 "counterexample \\(invariant\\), 4 steps:.*suspect +t=3"
       check heartbeat -p T=2 --prop no-false-suspicion --threads 1
       --junit ${WORK_DIR}/junit.xml --html ${WORK_DIR}/trace.html)
file(READ ${WORK_DIR}/junit.xml junit)
if(NOT junit MATCHES "<testsuites name=\"tioa-check\" tests=\"1\" failures=\"1\"")
  message(FATAL_ERROR "junit.xml: not one failed test case:\n${junit}")
endif()
file(READ ${WORK_DIR}/trace.html page)
if(NOT page MATCHES "<title>tioa-check: heartbeat \\(P=3, T=2\\)</title>.*<table class=\"state\">")
  message(FATAL_ERROR "trace.html: no title or no variable table")
endif()
expect(0 "no-timelock \\(deadlock\\): HOLDS" explore heartbeat --from start --threads 1)
expect(0 "suite: 4 checks \\(3 hold, 1 violated, 0 incomplete\\), 4 as expected.*: OK"
       suite --threads 1)
expect(2 "^heartbeat: error: unknown command 'round' \\(commands: list, check, explore, walk, replay, suite, sweep\\)\n$"
       round)
expect(2 "^heartbeat: error: parameter P = 0 is out of range 1..10\n$" check heartbeat -p P=0)
expect(2 "^heartbeat: error: unknown model 'fischer' \\(known: heartbeat\\)\n$" check fischer)
