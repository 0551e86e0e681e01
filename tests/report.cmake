# report.html, the interactive comparison page, in a real browser: headless Chromium
# driven by selenium through the Debian chromedriver (no network to fetch one), all
# installed by scripts/setup.sh (tests/report_html.py says what it checks). The system
# python3 runs it: Debian's python3-selenium lives there.
find_program(FS_CHROMIUM chromium)
find_program(FS_CHROMEDRIVER chromedriver)
find_program(FS_SYS_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT FS_CHROMIUM OR NOT FS_CHROMEDRIVER OR NOT FS_SYS_PYTHON3)
  message(FATAL_ERROR "chromium, chromedriver or /usr/bin/python3 not found: the report page's browser test "
                      "needs them. Run scripts/setup.sh (Debian chromium, chromium-driver, python3-selenium).")
endif()
add_test(NAME report_html COMMAND ${FS_SYS_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/report_html.py $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/report_html ${FS_CHROMIUM} ${FS_CHROMEDRIVER})
set_tests_properties(report_html PROPERTIES TIMEOUT 240 ENVIRONMENT "${FS_TEST_ENV}")
