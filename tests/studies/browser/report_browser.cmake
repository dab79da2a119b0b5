# The report's browser test (issue 25): headless Chromium loads REPORT/index.html through
# report_driver.html, searches for QUERY, expects EXPECT among the studies shown, opens EXPECT's first
# figure; it fails on RESULT: FAIL, on a timeout, or on any console message of the report's files.
# cmake -DCHROMIUM=… -DREPORT=dir -DQUERY=… -DEXPECT=ID -DWORK=dir -P report_browser.cmake
foreach(v CHROMIUM REPORT QUERY EXPECT WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "report_browser.cmake: -D${v}= is missing")
  endif()
endforeach()
foreach(f index.html lunr.min.js)
  if(NOT EXISTS ${REPORT}/${f})
    message(FATAL_ERROR "${REPORT}/${f} does not exist")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(driver "file://${CMAKE_CURRENT_LIST_DIR}/report_driver.html")
set(url "${driver}?report=file://${REPORT}/index.html&q=${QUERY}&expect=${EXPECT}")
execute_process(
  COMMAND ${CHROMIUM} --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions
          --user-data-dir=${WORK}/profile --allow-file-access-from-files --enable-logging=stderr --v=0
          --window-size=1400,1000 --virtual-time-budget=30000 --dump-dom ${url}
  OUTPUT_VARIABLE dom ERROR_VARIABLE log RESULT_VARIABLE rc TIMEOUT 120)
file(WRITE ${WORK}/dom.html "${dom}")
file(WRITE ${WORK}/chromium.log "${log}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "chromium exited with '${rc}' (log: ${WORK}/chromium.log)")
endif()
string(REGEX MATCH "RESULT: [^<]*" result "${dom}")
message(STATUS "${result}")
# Console messages (errors, uncaught exceptions, warnings) from the page: the report logs nothing.
string(REGEX MATCHALL "[^\n]*CONSOLE[^\n]*" console "${log}")
if(console)
  string(REPLACE ";" "\n" console "${console}")
  message(FATAL_ERROR "the report wrote to the console:\n${console}")
endif()
if(NOT result MATCHES "^RESULT: PASS")
  message(FATAL_ERROR "the browser test failed (DOM: ${WORK}/dom.html):\n${result}")
endif()
