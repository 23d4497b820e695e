# The hfshade command-line tool.
add_executable(hfshade ${CMAKE_CURRENT_SOURCE_DIR}/hfshade.c)
target_link_libraries(hfshade PRIVATE hfshade_lib hfshade_io hfshade_scene hfs_sh hfs_board)

# Deterministic procedural height fields for tests and benchmarks.
add_executable(hfgen ${CMAKE_CURRENT_SOURCE_DIR}/hfgen.c)
target_link_libraries(hfgen PRIVATE hfshade_io m)
