# The library as users get it: installed into a prefix of its own (fixture
# fs_installed), then the C example built against it (tests/c_example.sh) and
# the Python module's pytest suite run on it (tests/python/), and 50 Python
# sessions that must exit 0 with the CPU kept busy (python_exit). Not in the
# sanitizer builds: the module is loaded into an uninstrumented interpreter.
if(TARGET fluidsurf_lib AND FS_PYTHON3 AND NOT FS_SANITIZE AND FS_WITH_OSMESA)
  set(_prefix ${CMAKE_BINARY_DIR}/test-out/prefix)
  add_test(NAME install_prefix COMMAND ${CMAKE_COMMAND} -E env bash -c
           "rm -rf '${_prefix}' && '${CMAKE_COMMAND}' --install '${CMAKE_BINARY_DIR}' --prefix '${_prefix}' > /dev/null")
  set_tests_properties(install_prefix PROPERTIES FIXTURES_SETUP fs_installed)
  add_test(NAME c_example COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/c_example.sh ${CMAKE_SOURCE_DIR} ${_prefix}
           ${CMAKE_BINARY_DIR}/test-out/c_example
           ${CMAKE_SOURCE_DIR}/experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply)
  add_test(NAME python_api COMMAND ${FS_PYTHON3} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_SOURCE_DIR}/python)
  set_tests_properties(c_example python_api PROPERTIES FIXTURES_REQUIRED fs_installed TIMEOUT 300)
  set_tests_properties(c_example PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
  set_tests_properties(python_api PROPERTIES ENVIRONMENT
    "${FS_TEST_ENV};PYTHONPATH=${_prefix}/${FS_PYTHON_SITE};PYTHONDONTWRITEBYTECODE=1;FS_SRC=${CMAKE_SOURCE_DIR};FS_BIN=${_prefix}/bin/fluidsurf")
  # 50 sessions exit 0 with the CPU kept busy (tests/python_exit.sh): its two busy
  # loops take both cores, so ctest -j2 runs nothing beside it
  add_test(NAME python_exit COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/python_exit.sh ${FS_PYTHON3}
           ${CMAKE_SOURCE_DIR}/experiments/data/splashsurf/cube_2366_particles.vtk ${CMAKE_BINARY_DIR}/test-out/python_exit 50)
  set_tests_properties(python_exit PROPERTIES FIXTURES_REQUIRED fs_installed TIMEOUT 1200 PROCESSORS 2 ENVIRONMENT
    "${FS_TEST_ENV};PYTHONPATH=${_prefix}/${FS_PYTHON_SITE};PYTHONDONTWRITEBYTECODE=1")
  # pip install . into a fresh venv, this build packed as it is (tests/pip_install.sh;
  # scripts/test.sh runs the whole path, CMake building build-pip/ from the clean clone)
  add_test(NAME pip_install COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/pip_install.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}
           ${CMAKE_BINARY_DIR}/test-out/pip_install)
  set_tests_properties(pip_install PROPERTIES TIMEOUT 300 ENVIRONMENT "${FS_TEST_ENV}")
endif()
