# scripts/install.sh builds only what it installs, in build-install/ (its --dry-run plan
# and argument errors), installs this build as it is (--install-only), and
# cmake/openvdb.cmake hides FindOpenVDB's stray line.
# No code of the build runs: the normal build's alone.
if(FS_NORMAL_BUILD)
  add_test(NAME install_script COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install_script.sh ${CMAKE_SOURCE_DIR}
           ${CMAKE_BINARY_DIR}/test-out/install_script ${CMAKE_BINARY_DIR})
endif()
