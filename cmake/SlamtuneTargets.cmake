# Helpers that turn each folder of src/slamtune into an object library with its tests.

set(SLAMTUNE_FOLDERS "")
set(SLAMTUNE_FOLDER_TARGETS "")

function(slamtune_set_compile_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
  if(SLAMTUNE_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(SLAMTUNE_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()

# With SLAMTUNE_UNITY, `target` compiles as unity sources of SLAMTUNE_UNITY_BATCH_SIZE files each. The
# file-local names (anonymous namespaces, static functions) of one target's sources must then differ.
function(slamtune_set_unity target)
  if(SLAMTUNE_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${SLAMTUNE_UNITY_BATCH_SIZE})
  endif()
endfunction()

# slamtune_folder(name [DEPENDS folders...] [TEST_DEPENDS folders...] [EXTERNAL packages...])
#   DEPENDS       the folders the library's own code includes (declared before it, so layers go one way);
#   TEST_DEPENDS  further folders that only its tests and testing/ helpers include;
#   EXTERNAL      the packages the library's own code includes.
# Every .cc under src/slamtune/<name>, sub-folders included, is compiled into slamtune_<name>, except
# tests (*_test.cc) and testing/ helpers.
function(slamtune_folder name)
  cmake_parse_arguments(F "" "" "DEPENDS;TEST_DEPENDS;EXTERNAL" ${ARGN})
  foreach(dep IN LISTS F_DEPENDS F_TEST_DEPENDS)
    if(NOT DEFINED SLAMTUNE_CLOSURE_${dep})
      message(FATAL_ERROR "slamtune_folder(${name}): folder '${dep}' must be declared before '${name}'")
    endif()
  endforeach()
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
    slamtune_set_unity(${target})
  endif()
  # The folder and every folder it uses, directly or through another.
  set(closure ${name})
  foreach(dep IN LISTS F_DEPENDS)
    list(APPEND closure ${SLAMTUNE_CLOSURE_${dep}})
  endforeach()
  list(REMOVE_DUPLICATES closure)
  set(SLAMTUNE_CLOSURE_${name} ${closure} PARENT_SCOPE)
  set(SLAMTUNE_TEST_DEPS_${name} ${F_TEST_DEPENDS} PARENT_SCOPE)
  set(SLAMTUNE_FOLDERS ${SLAMTUNE_FOLDERS} ${name} PARENT_SCOPE)
  set(SLAMTUNE_FOLDER_TARGETS ${SLAMTUNE_FOLDER_TARGETS} ${target} PARENT_SCOPE)
endfunction()

# slamtune_folder_objects(out folders...): the object libraries of `folders` and of every folder they use.
# Object libraries pass their objects only to targets that link them directly, so an executable built on
# some folders links this whole list.
function(slamtune_folder_objects out)
  set(folders "")
  foreach(folder IN LISTS ARGN)
    if(NOT DEFINED SLAMTUNE_CLOSURE_${folder})
      message(FATAL_ERROR "slamtune_folder_objects: unknown folder '${folder}'")
    endif()
    list(APPEND folders ${SLAMTUNE_CLOSURE_${folder}})
  endforeach()
  list(REMOVE_DUPLICATES folders)
  list(TRANSFORM folders PREPEND slamtune_)
  set(${out} ${folders} PARENT_SCOPE)
endfunction()

# <folder>_tests: every *_test.cc of the folder (sub-folders included), plus its and common's testing/
# helpers, linked against the folder, the folders it uses and its TEST_DEPENDS. Each test is registered
# with CTest.
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
  slamtune_folder_objects(layers ${name} ${SLAMTUNE_TEST_DEPS_${name}})
  target_link_libraries(${name}_tests PRIVATE ${layers} GTest::gtest GTest::gtest_main GTest::gmock)
  target_compile_definitions(${name}_tests PRIVATE
    SLAMTUNE_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    SLAMTUNE_DATASETS_DIR="${CMAKE_SOURCE_DIR}/../shared/datasets")
  slamtune_set_compile_options(${name}_tests)
  slamtune_set_unity(${name}_tests)
  gtest_discover_tests(${name}_tests
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR}
    DISCOVERY_TIMEOUT 60
    PROPERTIES LABELS ${name})
endfunction()
