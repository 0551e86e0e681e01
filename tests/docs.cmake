# The documentation's generated tables match the committed CSVs (tests/readme_tables.sh).
add_test(NAME readme_tables COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/readme_tables.sh ${CMAKE_SOURCE_DIR})
