# Runs one tioa-check command line and checks what it did. Invoked by CTest as
#   cmake -DCMD=... -DEXPECT_EXIT=... [more -D...] -P run_cli.cmake
#
#   CMD                 the command line, its words separated by '|'
#   EXPECT_EXIT         the expected exit code
#   EXPECT_REGEX        regexes stdout must match, separated by '@@'
#   REJECT_REGEX        regexes stdout must not match, separated by '@@'
#   EXPECT_STDERR_REGEX regexes stderr must match, separated by '@@'
#   STDERR_LINES        the exact number of lines on stderr
#   JSON_CHECKER        cli_json_fields: run on stdout with JSON_ARGS ('@@'-separated)
#   JUNIT_FILE          a file the command writes: it must be well-formed XML (XML_CHECKER)
#                       and match JUNIT_REGEX ('@@'-separated)
#   WORK_DIR            where stdout is kept for the JSON checker

string(REPLACE "|" ";" command "${CMD}")
if(DEFINED JUNIT_FILE)
  file(REMOVE "${JUNIT_FILE}")
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                ERROR_VARIABLE err)

set(failures "")
# A function, not a macro: a macro would re-parse the backslashes of a regex in `message`.
function(fail message)
  set(failures "${failures}  ${message}\n" PARENT_SCOPE)
endfunction()

if(NOT "${exit_code}" STREQUAL "${EXPECT_EXIT}")
  fail("exit code ${exit_code}, expected ${EXPECT_EXIT}")
endif()

function(split_regexes text out_var)
  string(REPLACE "@@" ";" items "${text}")
  set(${out_var} "${items}" PARENT_SCOPE)
endfunction()

if(DEFINED EXPECT_REGEX)
  split_regexes("${EXPECT_REGEX}" regexes)
  foreach(regex IN LISTS regexes)
    if(NOT out MATCHES "${regex}")
      fail("stdout does not match '${regex}'")
    endif()
  endforeach()
endif()
if(DEFINED REJECT_REGEX)
  split_regexes("${REJECT_REGEX}" regexes)
  foreach(regex IN LISTS regexes)
    if(out MATCHES "${regex}")
      fail("stdout matches '${regex}' but must not")
    endif()
  endforeach()
endif()
if(DEFINED EXPECT_STDERR_REGEX)
  split_regexes("${EXPECT_STDERR_REGEX}" regexes)
  foreach(regex IN LISTS regexes)
    if(NOT err MATCHES "${regex}")
      fail("stderr does not match '${regex}'")
    endif()
  endforeach()
endif()
if(DEFINED STDERR_LINES)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines lines)
  if(NOT lines EQUAL STDERR_LINES)
    fail("stderr has ${lines} lines, expected ${STDERR_LINES}")
  endif()
endif()

if(DEFINED JSON_CHECKER)
  file(MAKE_DIRECTORY "${WORK_DIR}")
  set(json_file "${WORK_DIR}/stdout.json")
  file(WRITE "${json_file}" "${out}")
  string(REPLACE "@@" ";" json_args "${JSON_ARGS}")
  execute_process(COMMAND "${JSON_CHECKER}" "${json_file}" ${json_args}
                  RESULT_VARIABLE json_exit ERROR_VARIABLE json_err)
  if(NOT json_exit EQUAL 0)
    fail("JSON checks failed:\n${json_err}")
  endif()
endif()

if(DEFINED JUNIT_FILE)
  if(NOT EXISTS "${JUNIT_FILE}")
    fail("${JUNIT_FILE} was not written")
  else()
    execute_process(COMMAND "${XML_CHECKER}" "${JUNIT_FILE}" RESULT_VARIABLE xml_exit
                    ERROR_VARIABLE xml_err)
    if(NOT xml_exit EQUAL 0)
      fail("${JUNIT_FILE} is not well-formed: ${xml_err}")
    endif()
    file(READ "${JUNIT_FILE}" junit)
    split_regexes("${JUNIT_REGEX}" regexes)
    foreach(regex IN LISTS regexes)
      if(NOT junit MATCHES "${regex}")
        fail("${JUNIT_FILE} does not match '${regex}'")
      endif()
    endforeach()
  endif()
endif()

if(NOT failures STREQUAL "")
  message(FATAL_ERROR "${CMD}\n${failures}--- stdout:\n${out}--- stderr:\n${err}")
endif()
