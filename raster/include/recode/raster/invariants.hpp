#pragma once
// Invariants at the raster stages' boundaries (block alignment, the fixed-point range, non-empty
// coverage masks, rectangles inside the framebuffer), checked as reference renderers do: on in
// Debug builds (no NDEBUG) and in any build configured with RECODE_CHECK_INVARIANTS=ON (the
// sanitizer builds), compiled out otherwise so the reference pays nothing for them. A failure
// is a bug in this library, never bad input (the device interface rejects that with
// std::invalid_argument first): it prints what broke and where, then aborts.

#if !defined(NDEBUG) || defined(RECODE_CHECK_INVARIANTS)
#define RECODE_INVARIANTS_ON 1
#define RECODE_INVARIANT(condition, what) \
  ((condition) ? static_cast<void>(0)     \
               : ::recode::raster::invariantFailed(#condition, what, __FILE__, __LINE__))
#else
#define RECODE_INVARIANTS_ON 0
// Not evaluated, but still compiled, so a check cannot rot in the builds that skip it.
#define RECODE_INVARIANT(condition, what) static_cast<void>(sizeof(static_cast<bool>(condition)))
#endif

namespace recode::raster {

// Writes "recode: invariant failed: <what> (<condition>) at <file>:<line>" to stderr and aborts.
[[noreturn]] void invariantFailed(const char* condition, const char* what, const char* file,
                                  int line);

}  // namespace recode::raster
