# ROS tests beyond the one-file-one-executable rule (included from CMakeLists.txt):
#  - ros/npm_setup: installs the independent serializer test_wire compares with (skips without
#    npm or registry); test_wire requires it as a fixture;
#  - the Fast DDS peer for test_fastdds, compiled only in the test build and only when Fast DDS
#    (libfastrtps-dev) is found; C++ is enabled for it alone.
add_test(NAME ros/npm_setup COMMAND sh ${CMAKE_SOURCE_DIR}/tests/ros/npm_setup.sh ${CMAKE_BINARY_DIR}/npm)
set_tests_properties(ros/npm_setup PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 240 FIXTURES_SETUP ros_npm)
if(TEST ros/test_wire)
  set_tests_properties(ros/test_wire PROPERTIES FIXTURES_REQUIRED ros_npm)
endif()
if(TARGET ros_test_wire)
  target_compile_definitions(ros_test_wire PRIVATE SP_NPM_DIR="${CMAKE_BINARY_DIR}/npm")
endif()
