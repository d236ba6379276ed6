# Helpers shared by every module of Impasto.

# Warnings for the project's own targets (never for generated or third-party code).
function(impasto_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  # GCC 12 at -O3 reports -Wrestrict on `"literal" + std::string` inside libstdc++
  # (GCC bug 105329, fixed in 13): a false positive, not a finding in our code.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(IMPASTO_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# impasto_module(NAME [DEPS ...]): a static library impasto_NAME (alias impasto::NAME) from
# NAME/src/*.cpp with public headers in NAME/include/impasto/NAME/.
function(impasto_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(impasto_${name} STATIC ${sources})
  add_library(impasto::${name} ALIAS impasto_${name})
  target_include_directories(impasto_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
                                             PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_compile_features(impasto_${name} PUBLIC cxx_std_20)
  target_link_libraries(impasto_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  impasto_warnings(impasto_${name})
endfunction()

# The definitions every test program gets.
function(impasto_test_definitions target)
  target_compile_definitions(${target} PRIVATE
    IMPASTO_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    IMPASTO_TEST_FILES_DIR="${PROJECT_SOURCE_DIR}/tests/data/files")
endfunction()

# Test programs' own code is light (the libraries they call keep their optimisation), so the
# sanitizer build compiles it at -O0 and the Release build at -O1: about a quarter less of each
# build's time in CI (a test source at -O3 takes up to twice as long as at -O1).
#
# GCC 12 reports false -Warray-bounds and -Wstringop-overflow/-overread inside libstdc++
# (std::string, vectors of variants) wherever its inliner happens to land, and test programs,
# which build many such values by hand, hit them again and again (GCC bug 105651 and its kin,
# fixed in 13): they are off for test programs only; the libraries keep them.
function(impasto_test_optimisation target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Debug>:-O0> $<$<CONFIG:Release>:-O1>)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overflow
                                             -Wno-stringop-overread)
  endif()
endfunction()

# A test program compiles as unity batches (IMPASTO_TEST_UNITY_BATCH sources a compiler run):
# its sources share most headers, parsed once a batch instead of once a source (the Release
# build's test objects: about 600 s of CPU one source each; 276, 254 and 248 s in batches of 4,
# 6 and 8, rebuilt in 140, 130 and 241 s on two cores: 6). Libraries are not unity builds: their
# floating-point results must not depend on what inlines beside what.
set(IMPASTO_TEST_UNITY_BATCH 6 CACHE STRING "Sources of a test program compiled together (0: one batch)")
function(impasto_test_unity_build target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                                             UNITY_BUILD_BATCH_SIZE ${IMPASTO_TEST_UNITY_BATCH})
endfunction()

# impasto_test(NAME SOURCES... DEPS ... [GPU]): one GoogleTest executable registered with
# CTest. GPU: it renders through Mesa's llvmpipe, whose JIT-compiled shader code allocates from
# frames with no module name for tests/lsan.supp to match, so under the sanitizers its leak
# check is off (every other ASan and UBSan check stays on), as for tests/gl.
function(impasto_test name)
  cmake_parse_arguments(ARG "GPU" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  impasto_test_definitions(${name})
  impasto_test_optimisation(${name})
  impasto_warnings(${name})
  # GoogleTest's headers are parsed once for all test programs: one precompiled header, built
  # by a target with the same flags (an empty source), which every test program reuses.
  if(NOT TARGET impasto_gtest_pch)
    set(pch_source ${PROJECT_BINARY_DIR}/impasto_gtest_pch.cpp)
    file(CONFIGURE OUTPUT ${pch_source} CONTENT "// The precompiled header's own source.\n")
    add_library(impasto_gtest_pch OBJECT ${pch_source})
    target_link_libraries(impasto_gtest_pch PRIVATE GTest::gtest)
    impasto_test_definitions(impasto_gtest_pch)
    impasto_test_optimisation(impasto_gtest_pch)
    impasto_warnings(impasto_gtest_pch)
    target_precompile_headers(impasto_gtest_pch PRIVATE <gtest/gtest.h>)
  endif()
  target_precompile_headers(${name} REUSE_FROM impasto_gtest_pch)
  impasto_test_unity_build(${name})
  # No $IMPASTO_DATA_DIR: the tests find data/ as any build-tree program does (files::data_dir).
  if(IMPASTO_SANITIZE)
    impasto_sharded_test(${name} ${ARG_GPU})
  else()
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
  endif()
endfunction()

# Under the sanitizers a test process costs about 0.1 s to start and to leak-check at its exit,
# more than most tests take, so there a test program runs as IMPASTO_SANITIZER_SHARDS CTest
# entries, each a GoogleTest shard (every test runs in exactly one), instead of one process a
# test. The Release build keeps one CTest entry a test.
set(IMPASTO_SANITIZER_SHARDS 3 CACHE STRING "CTest entries a test program runs as under the sanitizers")
function(impasto_sharded_test name gpu)
  set(leak_check "")
  if(gpu)
    set(leak_check ";ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
  endif()
  math(EXPR last "${IMPASTO_SANITIZER_SHARDS} - 1")
  foreach(shard RANGE ${last})
    add_test(NAME ${name}.shard${shard} COMMAND ${name})
    set_tests_properties(${name}.shard${shard} PROPERTIES ENVIRONMENT
      "GTEST_TOTAL_SHARDS=${IMPASTO_SANITIZER_SHARDS};GTEST_SHARD_INDEX=${shard}${leak_check}")
  endforeach()
endfunction()
