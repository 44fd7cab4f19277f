# recode_warnings: the warning flags of our own targets (never applied to third-party headers,
# which are included as SYSTEM by their imported targets), -Werror with RECODE_WERROR. Included
# by the top-level project and by tests/link's project, so that a library's sources compile with
# the same command line in both: the compiler cache (scripts/build.sh) then compiles them once.
if(NOT TARGET recode_warnings)
  add_library(recode_warnings INTERFACE)
  target_compile_options(recode_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                                   -Wno-sign-conversion)
  if(RECODE_WERROR)
    target_compile_options(recode_warnings INTERFACE -Werror)
  endif()
endif()
