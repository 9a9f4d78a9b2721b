# sextant_add_module(<name> SOURCES ... PUBLIC_DEPS ... PRIVATE_DEPS ...)
# Creates the shared library sextant_<name> with alias Sextant::<name>; headers live in
# <name>/include/sextant/<name>/.
function(sextant_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  set(target sextant_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(Sextant::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME sextant_${name}
                                             UNITY_BUILD ${SEXTANT_UNITY_BUILD})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE sextant_options ${ARG_PRIVATE_DEPS})
  # Calls inside the library go to its own functions. Without this, every Eigen (or other
  # header-only) template instance the library does not inline is looked up at run time, and the
  # first definition loaded wins: the test executables', built at -O1/-O0 (sextant_add_test), so the
  # libraries' matrix products ran 20–50x slower under the tests than in the `sextant` binary.
  target_link_options(${target} PRIVATE LINKER:-Bsymbolic-functions)
  install(TARGETS ${target} EXPORT SextantTargets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# sextant_test_settings(<target>): what every test executable compiles with. The test executables
# share one precompiled header (tests/common/test_pch.hpp, built by sextant_test_pch in
# tests/CMakeLists.txt), so their flags must be identical: they all come from here.
function(sextant_test_settings target)
  target_link_libraries(${target} PRIVATE GTest::gtest sextant_options)
  set_target_properties(${target} PROPERTIES SEXTANT_NO_UBSAN ON)  # see CompilerOptions.cmake
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests/common)
  target_compile_definitions(${target} PRIVATE
    SEXTANT_DATA_DIR="${PROJECT_SOURCE_DIR}/data"
    SEXTANT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # The test files themselves build at a lower level than the libraries they exercise, which keep
  # the build type's: -O1 in Release (half the compile time of -O3 per test file), -O0 under the
  # sanitizers (scripts/sanitize.sh builds at -O1; a third less). The later -O option wins. At -O1
  # GCC 12 reports -Wmaybe-uninitialized inside Eigen's own copy constructors (false positives,
  # e.g. tests/filters/eseif_test.cpp's model matrices), so test files at -O1 go without that one.
  if(SEXTANT_SANITIZE)
    target_compile_options(${target} PRIVATE -O0)
  else()
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1 -Wno-maybe-uninitialized>)
  endif()
  # A precompiled header that no longer matches the flags is an error, not a silent full parse.
  target_compile_options(${target} PRIVATE -Winvalid-pch)
endfunction()

# sextant_add_test(<name> SOURCES ... DEPS ...): one GoogleTest executable per module.
function(sextant_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  # Batches of 8: the file-local helpers of one executable's files must not repeat names.
  set_target_properties(${name} PROPERTIES UNITY_BUILD ${SEXTANT_UNITY_BUILD} UNITY_BUILD_BATCH_SIZE 8)
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main)
  sextant_test_settings(${name})
  if(SEXTANT_TEST_PCH)
    target_precompile_headers(${name} REUSE_FROM sextant_test_pch)
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endfunction()
