# Helpers that turn each folder of src/slamtune into an object library with its tests.

set(SLAMTUNE_FOLDERS "")
set(SLAMTUNE_FOLDER_TARGETS "")

function(slamtune_set_compile_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
  if(SLAMTUNE_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()

# slamtune_folder(name [DEPENDS lower folders...] [EXTERNAL packages...])
function(slamtune_folder name)
  cmake_parse_arguments(F "" "" "DEPENDS;EXTERNAL" ${ARGN})
  set(dir ${CMAKE_SOURCE_DIR}/src/slamtune/${name})
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${dir}/*.cc)
  list(FILTER srcs EXCLUDE REGEX "_test\\.cc$")
  list(FILTER srcs EXCLUDE REGEX "/testing/")
  set(target slamtune_${name})
  if(srcs)
    add_library(${target} OBJECT ${srcs})
    set(scope PUBLIC)
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope} ${CMAKE_SOURCE_DIR}/src)
  foreach(dep IN LISTS F_DEPENDS)
    target_link_libraries(${target} ${scope} slamtune_${dep})
  endforeach()
  if(F_EXTERNAL)
    target_link_libraries(${target} ${scope} ${F_EXTERNAL})
  endif()
  if(srcs)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    slamtune_set_compile_options(${target})
  endif()
  set(SLAMTUNE_FOLDERS ${SLAMTUNE_FOLDERS} ${name} PARENT_SCOPE)
  set(SLAMTUNE_FOLDER_TARGETS ${SLAMTUNE_FOLDER_TARGETS} ${target} PARENT_SCOPE)
  set(SLAMTUNE_DEPS_${name} ${F_DEPENDS} PARENT_SCOPE)
endfunction()

# <folder>_tests: every *_test.cc of the folder, plus its and common's testing/ helpers, linked against the
# folder and the folders below it. Each test is registered with CTest.
function(slamtune_folder_tests name)
  set(dir ${CMAKE_SOURCE_DIR}/src/slamtune/${name})
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/*_test.cc)
  file(GLOB_RECURSE helpers CONFIGURE_DEPENDS ${dir}/testing/*.cc)
  # common's helpers (temporary folders, ...) serve every folder's tests.
  if(NOT name STREQUAL "common")
    file(GLOB_RECURSE common_helpers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/slamtune/common/testing/*.cc)
    list(APPEND helpers ${common_helpers})
  endif()
  list(FILTER helpers EXCLUDE REGEX "_test\\.cc$")
  if(NOT tests)
    return()
  endif()
  add_executable(${name}_tests ${tests} ${helpers})
  # Object libraries pass their objects only to targets that link them directly: name every layer.
  set(layers slamtune_${name})
  foreach(dep IN LISTS SLAMTUNE_DEPS_${name})
    list(APPEND layers slamtune_${dep})
  endforeach()
  target_link_libraries(${name}_tests PRIVATE ${layers} GTest::gtest GTest::gtest_main GTest::gmock)
  target_compile_definitions(${name}_tests PRIVATE
    SLAMTUNE_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    SLAMTUNE_DATASETS_DIR="${CMAKE_SOURCE_DIR}/../shared/datasets")
  slamtune_set_compile_options(${name}_tests)
  gtest_discover_tests(${name}_tests
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR}
    DISCOVERY_TIMEOUT 60
    PROPERTIES LABELS ${name})
endfunction()
