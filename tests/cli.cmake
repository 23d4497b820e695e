# The command-line tool end to end: broken inputs and a good render.
add_test(NAME cli_bad_inputs
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_bad_inputs.sh
                 $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen>
                 ${CMAKE_CURRENT_SOURCE_DIR}/data/broken)
set_tests_properties(cli_bad_inputs PROPERTIES LABELS io TIMEOUT 300)
