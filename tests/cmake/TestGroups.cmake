# manylights_add_test_groups(TARGET PREFIX prefix [FILTER gtest-filter] [GROUP_SIZE n]
#                            [PROPERTIES name value ...])
#
# Registers the GoogleTest program TARGET's tests with CTest a few to a process, as
# write_test_groups.py says (docs/testing.md, "The suite's time"): after each build the program
# lists its tests, and the script writes one CTest test per group, named PREFIX + the
# parameterised test or the plain suite, with " (part k of n)" where one has more than
# GROUP_SIZE (8) tests. PROPERTIES are set on every group, as gtest_discover_tests' are.
# Each call is also recorded for manylights_check_test_groups().
function(manylights_add_test_groups TARGET)
  cmake_parse_arguments(ARG "" "PREFIX;FILTER;GROUP_SIZE" "PROPERTIES" ${ARGN})
  if(NOT ARG_GROUP_SIZE)
    set(ARG_GROUP_SIZE 8)
  endif()
  string(MAKE_C_IDENTIFIER "${TARGET}_${ARG_PREFIX}" base)
  set(tests_file "${CMAKE_CURRENT_BINARY_DIR}/${base}_groups.cmake")
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${base}_include.cmake")
  set(property_args)
  set(properties ${ARG_PROPERTIES})
  while(properties)
    list(POP_FRONT properties name value)
    if(NOT DEFINED value)
      message(FATAL_ERROR "manylights_add_test_groups(${TARGET}): PROPERTIES ${name} has no value")
    endif()
    list(APPEND property_args --property "${name}" "${value}")
    unset(value)
  endwhile()
  add_custom_command(
    TARGET ${TARGET} POST_BUILD
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/write_test_groups.py"
            --executable "$<TARGET_FILE:${TARGET}>" --prefix "${ARG_PREFIX}" "--filter=${ARG_FILTER}"
            --group-size "${ARG_GROUP_SIZE}" --output "${tests_file}" ${property_args}
    BYPRODUCTS "${tests_file}"
    VERBATIM)
  file(WRITE "${include_file}"
       "if(EXISTS \"${tests_file}\")\n"
       "  include(\"${tests_file}\")\n"
       "else()\n"
       "  add_test(${ARG_PREFIX}NOT_BUILT ${TARGET}_NOT_BUILT)\n"
       "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
  set_property(GLOBAL APPEND PROPERTY MANYLIGHTS_TEST_GROUP_FILES "${tests_file}"
                                                                 "$<TARGET_FILE:${TARGET}>=${ARG_FILTER}")
endfunction()

# The CTest test scripts.write_test_groups_py: the script's own tests, and that each program's
# groups (every manylights_add_test_groups call before this one) run each of its tests once.
function(manylights_check_test_groups)
  get_property(pairs GLOBAL PROPERTY MANYLIGHTS_TEST_GROUP_FILES)
  add_test(NAME scripts.write_test_groups_py
           COMMAND Python3::Interpreter "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/test_write_test_groups.py" ${pairs})
endfunction()
