# Runs one tioa-check command line with --html PAGE and checks the page. Invoked by CTest as
#   cmake -DCMD=... -DEXPECT_EXIT=... -DPAGE=... -DXML_CHECKER=... [more -D...] -P html_page.cmake
#
#   CMD          the command line, its words separated by '|' (it must write PAGE)
#   EXPECT_EXIT  the expected exit code
#   PAGE         the HTML file the command writes: it must be well-formed XML with root <html>
#   PAGE_REGEX   regexes the page must match, separated by '@@'
#   FRAMES       the exact number of frames (<section class="frame...) on the page
#   CHROMIUM     ON: also open the page in headless Chromium and check that the script ran
#                (the status line "step 0 of N" is in the DOM, N + 1 the page's frames), that
#                the frames are there and that the DOM matches PAGE_REGEX too; prints "SKIPPED: ..." (the test is then reported as skipped)
#                when no chromium is installed

string(REPLACE "|" ";" command "${CMD}")
file(REMOVE "${PAGE}")
execute_process(COMMAND ${command} RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                ERROR_VARIABLE err)

set(failures "")
function(fail message)
  set(failures "${failures}  ${message}\n" PARENT_SCOPE)
endfunction()

function(count_frames text out_var)
  string(REGEX MATCHALL "<section class=\"frame" matches "${text}")
  list(LENGTH matches n)
  set(${out_var} ${n} PARENT_SCOPE)
endfunction()

if(NOT "${exit_code}" STREQUAL "${EXPECT_EXIT}")
  fail("exit code ${exit_code}, expected ${EXPECT_EXIT}")
endif()
if(NOT EXISTS "${PAGE}")
  fail("${PAGE} was not written")
else()
  execute_process(COMMAND "${XML_CHECKER}" "${PAGE}" html RESULT_VARIABLE xml_exit
                  ERROR_VARIABLE xml_err)
  if(NOT xml_exit EQUAL 0)
    fail("${PAGE} is not well-formed: ${xml_err}")
  endif()
  file(READ "${PAGE}" page)
  if(page MATCHES "(src|href)=\"(https?:)?//")
    fail("${PAGE} refers to an external resource")
  endif()
  string(REPLACE "@@" ";" regexes "${PAGE_REGEX}")
  foreach(regex IN LISTS regexes)
    if(NOT page MATCHES "${regex}")
      fail("${PAGE} does not match '${regex}'")
    endif()
  endforeach()
  if(DEFINED FRAMES)
    count_frames("${page}" frames)
    if(NOT frames EQUAL FRAMES)
      fail("${PAGE} has ${frames} frames, expected ${FRAMES}")
    endif()
  endif()
endif()

if(CHROMIUM AND failures STREQUAL "")
  find_program(chromium NAMES chromium chromium-browser google-chrome)
  if(NOT chromium)
    message("SKIPPED: no chromium installed (tools/install-deps.sh installs Debian's chromium)")
    return()
  endif()
  execute_process(COMMAND "${chromium}" --headless --disable-gpu --no-sandbox
                          --user-data-dir=${PAGE}.profile --dump-dom "file://${PAGE}"
                  RESULT_VARIABLE chromium_exit OUTPUT_VARIABLE dom ERROR_VARIABLE chromium_err
                  TIMEOUT 60)
  if(NOT chromium_exit EQUAL 0)
    fail("chromium exited with ${chromium_exit}: ${chromium_err}")
  endif()
  count_frames("${page}" page_frames)
  math(EXPR last "${page_frames} - 1")
  if(NOT dom MATCHES "<span class=\"status\">step 0 of ${last}</span>")
    fail("the DOM has no status line 'step 0 of ${last}': the script did not run")
  endif()
  count_frames("${dom}" frames)
  if(NOT frames EQUAL page_frames)
    fail("the DOM has ${frames} frames, the page ${page_frames}")
  endif()
  foreach(regex IN LISTS regexes)
    if(NOT dom MATCHES "${regex}")
      fail("the DOM does not match '${regex}'")
    endif()
  endforeach()
endif()

if(NOT failures STREQUAL "")
  message(FATAL_ERROR "${CMD}\n${failures}--- stdout:\n${out}--- stderr:\n${err}")
endif()
