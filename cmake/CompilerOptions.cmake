# Warning and sanitizer flags, applied to every Sextant target through sextant_options.
add_library(sextant_options INTERFACE)
target_compile_options(sextant_options INTERFACE -Wall -Wextra -Wpedantic)
if(SEXTANT_WERROR)
  target_compile_options(sextant_options INTERFACE -Werror)
endif()
if(SEXTANT_SANITIZE)
  target_compile_options(sextant_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                   -fno-sanitize-recover=undefined)
  target_link_options(sextant_options INTERFACE -fsanitize=address,undefined)
endif()
install(TARGETS sextant_options EXPORT SextantTargets)
