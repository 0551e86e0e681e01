# Checks of committed files alone (no code of the build runs): the normal build's.
if(NOT FS_NORMAL_BUILD)
  return()
endif()
# The documentation's generated tables match the committed CSVs (tests/readme_tables.sh).
add_test(NAME readme_tables COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/readme_tables.sh ${CMAKE_SOURCE_DIR})
# results/gpu/README.md is what experiments/gpu/report.py makes of the CSVs beside it.
add_test(NAME gpu_readme COMMAND python3 ${CMAKE_SOURCE_DIR}/experiments/gpu/report.py --check ${CMAKE_SOURCE_DIR}/results/gpu)
# results/README.md's commit column names each row's main CSV's commit.
add_test(NAME results_index COMMAND python3 ${CMAKE_SOURCE_DIR}/scripts/check_index.py ${CMAKE_SOURCE_DIR}/results/README.md)
# Every measured number typed in the READMEs' prose carries <!--n CSV EXPR FORMAT--> and equals
# what that CSV gives; the index's verdicts have no measured number without one.
add_test(NAME results_numbers COMMAND python3 ${CMAKE_SOURCE_DIR}/scripts/check_numbers.py)
# and on files made to fail: a wrong number in docs/DESIGN.md, a time or a verdict's integer
# without a note, the aggregates (tests/check_numbers.sh)
add_test(NAME check_numbers COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_numbers.sh ${CMAKE_SOURCE_DIR}
         ${CMAKE_BINARY_DIR}/test-out/check_numbers)
# Every committed CSV under results/ names a clean commit (or awaits a listed re-run).
add_test(NAME results_clean COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/check_results.sh ${CMAKE_SOURCE_DIR})
# The bounds that run_all.sh --quick checks each study's numbers against
# (scripts/check_quick.py): every study has one, the committed results meet
# them, and a broken number fails naming the study, the CSV and the number. The quick
# studies themselves run in CI through scripts/test.sh, not here.
add_test(NAME quick_bounds COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_quick.sh ${CMAKE_SOURCE_DIR}
         ${CMAKE_BINARY_DIR}/test-out/quick_bounds)
