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

set(SP_FASTDDS_PEER_PATH "")
if(SP_HAVE_CYCLONEDDS)
  find_package(fastrtps QUIET)
  find_package(fastcdr QUIET)
  include(CheckLanguage)
  check_language(CXX)
  if(fastrtps_FOUND AND fastcdr_FOUND AND CMAKE_CXX_COMPILER)
    enable_language(CXX)
    add_executable(ros_fastdds_peer ${CMAKE_SOURCE_DIR}/tests/ros/fastdds_peer.cpp)
    # A reference tool, not code under test: built without the sanitizer options (Fast DDS 2.9's
    # own statistics reader trips ASan's new/delete size check when the peer is instrumented).
    set_target_properties(ros_fastdds_peer PROPERTIES CXX_STANDARD 14 CXX_STANDARD_REQUIRED ON
                          COMPILE_OPTIONS "" LINK_OPTIONS "")
    target_link_libraries(ros_fastdds_peer PRIVATE fastrtps fastcdr)
    set(SP_FASTDDS_PEER_PATH $<TARGET_FILE:ros_fastdds_peer>)
    if(TARGET ros_test_fastdds)
      add_dependencies(ros_test_fastdds ros_fastdds_peer)
    endif()
  endif()
endif()
message(STATUS "semsplat: Fast DDS test peer ${fastrtps_FOUND}")
if(TARGET ros_test_fastdds)
  target_compile_definitions(ros_test_fastdds PRIVATE SP_FASTDDS_PEER="${SP_FASTDDS_PEER_PATH}")
endif()

# Tests that use Cyclone's API directly (a bare "tap" participant): only with Cyclone.
if(SP_HAVE_CYCLONEDDS)
  file(GLOB SP_ROS_DDS_TESTS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/ros/dds/test_*.c)
  foreach(src ${SP_ROS_DDS_TESTS})
    get_filename_component(name ${src} NAME_WE)
    add_executable(ros_dds_${name} ${src})
    target_include_directories(ros_dds_${name} PRIVATE ${CMAKE_SOURCE_DIR}/src ${CMAKE_SOURCE_DIR}/tests
                               ${CMAKE_SOURCE_DIR}/tests/ros ${SP_ROS_IDL_OUT})
    target_link_libraries(ros_dds_${name} PRIVATE semsplat CycloneDDS::ddsc m)
    target_compile_options(ros_dds_${name} PRIVATE -std=gnu11)
    target_compile_definitions(ros_dds_${name} PRIVATE
      SP_SOURCE_DIR="${CMAKE_SOURCE_DIR}" SP_BUILD_DIR="${CMAKE_BINARY_DIR}")
    add_test(NAME ros/dds/${name} COMMAND ros_dds_${name} WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    set_tests_properties(ros/dds/${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
  endforeach()
endif()
