# structure.cmake — the code's shape, checked (issue 14; brief "Structure"):
# no function in runtime/ over 120 lines; runtime/ includes nothing from
# board/ and the hfshade tool links no board library.
add_test(NAME function_length
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/function_length.sh ${PROJECT_SOURCE_DIR} 120)
add_test(NAME library_stands_alone
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/structure.sh ${PROJECT_SOURCE_DIR}
                 ${PROJECT_BINARY_DIR})
set_tests_properties(function_length library_stands_alone PROPERTIES LABELS unit TIMEOUT 60)
