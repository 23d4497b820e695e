# structure.cmake — the code's shape, checked (issue 14; brief "Structure"):
# no function in runtime/ over 100 lines (issue 34; was 120); no two
# translation units of the runtime libraries call each other (issue 34;
# reads the built libraries); runtime/ includes nothing from board/ and the
# hfshade tool links no board library.
add_test(NAME function_length
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/function_length.sh ${PROJECT_SOURCE_DIR} 100)
add_test(NAME no_file_cycles
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/no_file_cycles.sh ${PROJECT_BINARY_DIR})
add_test(NAME library_stands_alone
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/structure.sh ${PROJECT_SOURCE_DIR}
                 ${PROJECT_BINARY_DIR})
set_tests_properties(function_length no_file_cycles library_stands_alone PROPERTIES LABELS unit TIMEOUT 60)
# runtime/ in folders by role (issue 34): every #include keeps the rule of
# its folder's README.md ("May include:"), and the check catches planted
# violations (core -> cpu/gl/scene, truth -> gles/cpu, runtime -> board/tools).
add_test(NAME include_rules
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/include_rules.sh ${PROJECT_SOURCE_DIR})
add_test(NAME include_rules_planted
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/include_rules_planted.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(include_rules include_rules_planted PROPERTIES LABELS unit TIMEOUT 120)
# tools/mutations.txt still applies (session 30): each mutant's FIND occurs
# exactly once in its file, so a rewrite that moves a mutant's code fails
# here at once, not in the nightly tools/mutate.sh (which reports it STALE).
add_test(NAME mutations_apply
         COMMAND bash ${PROJECT_SOURCE_DIR}/tools/mutations_check.sh)
set_tests_properties(mutations_apply PROPERTIES LABELS unit TIMEOUT 60)
