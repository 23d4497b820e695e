# hfs_cli_usage: the one-line usage error every program prints on a bad
# command line (issue 34, tools/cli_usage.h); the tools, the board's
# programs and the measurement tools link it.
add_library(hfs_cli_usage STATIC ${CMAKE_CURRENT_LIST_DIR}/cli_usage.c)
target_include_directories(hfs_cli_usage PUBLIC ${CMAKE_CURRENT_LIST_DIR})
