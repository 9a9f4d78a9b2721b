# Warning and sanitizer flags, applied to every Sextant target through sextant_options.
add_library(sextant_options INTERFACE)
target_compile_options(sextant_options INTERFACE -Wall -Wextra -Wpedantic)
if(SEXTANT_WERROR)
  target_compile_options(sextant_options INTERFACE -Werror)
endif()
if(SEXTANT_FUZZ)
  # libFuzzer harnesses (fuzz/): clang only; everything is instrumented for coverage and runs under
  # ASan + UBSan, so the sanitizer block below applies too.
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "SEXTANT_FUZZ needs clang: configure with -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
  endif()
  target_compile_options(sextant_options INTERFACE -fsanitize=fuzzer-no-link)
endif()
if(SEXTANT_SANITIZE OR SEXTANT_FUZZ)
  # ASan everywhere. UBSan in the code under test, but not in targets marked SEXTANT_NO_UBSAN:
  # - the test files (sextant_test_settings): what they call in the libraries is checked there.
  #   UBSan's checks in their own Eigen and GoogleTest code almost doubled their compile time
  #   (tests/filters/eseif_test.cpp at -O0: 305 s with it, 165 s without);
  # - the experiments library (experiments/CMakeLists.txt): runs, configs and reports, which call the
  #   checked algorithm libraries; its config and JSON readers run under UBSan in the fuzz harnesses.
  #   409 s of the sanitizer build's 2110 s of compile time with UBSan, about 280 s without.
  # float-cast-overflow (a NaN or out-of-range double converted to int) is in clang's `undefined`
  # group but not GCC's.
  target_compile_options(sextant_options INTERFACE -fsanitize=address -fno-omit-frame-pointer
    "$<$<NOT:$<BOOL:$<TARGET_PROPERTY:SEXTANT_NO_UBSAN>>>:-fsanitize=undefined,float-cast-overflow;-fno-sanitize-recover=undefined,float-cast-overflow>")
  target_link_options(sextant_options INTERFACE -fsanitize=address,undefined,float-cast-overflow)
  # Eigen stops trusting glibc's 16-byte malloc alignment under ASan and switches to its own
  # aligned allocator, but Debian's prebuilt PCL allocates its Eigen members with plain malloc:
  # objects built in PCL and freed in our code would then be freed the wrong way. Keep Eigen's
  # allocation identical to PCL's (x86-64 glibc and ASan both return 16-byte aligned blocks).
  target_compile_definitions(sextant_options INTERFACE EIGEN_MALLOC_ALREADY_ALIGNED=1)
endif()
install(TARGETS sextant_options EXPORT SextantTargets)
