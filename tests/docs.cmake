# The documentation's generated tables match the committed CSVs (tests/readme_tables.sh).
add_test(NAME readme_tables COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/readme_tables.sh ${CMAKE_SOURCE_DIR})
# results/gpu/README.md is what experiments/gpu/report.py makes of the CSVs beside it.
add_test(NAME gpu_readme COMMAND python3 ${CMAKE_SOURCE_DIR}/experiments/gpu/report.py --check ${CMAKE_SOURCE_DIR}/results/gpu)
# results/README.md's commit column names each row's main CSV's commit.
add_test(NAME results_index COMMAND python3 ${CMAKE_SOURCE_DIR}/experiments/tools/check_index.py ${CMAKE_SOURCE_DIR}/results/README.md)
