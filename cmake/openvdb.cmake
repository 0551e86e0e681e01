# find_package(OpenVDB) as Debian ships it (docs/DESIGN.md, "Platform facts"): TBB first,
# its FindOpenVDB.cmake in a folder of its own, and that module's stray
# message("COMPONENT = openvdb") (a bare message: level NOTICE) hidden while it runs;
# its warnings and errors still show. tests/install.cmake checks the quiet.
find_package(TBB CONFIG REQUIRED)
list(APPEND CMAKE_MODULE_PATH "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB")
set(_fs_log_level "${CMAKE_MESSAGE_LOG_LEVEL}")
set(CMAKE_MESSAGE_LOG_LEVEL WARNING)
find_package(OpenVDB REQUIRED)
set(CMAKE_MESSAGE_LOG_LEVEL "${_fs_log_level}")
