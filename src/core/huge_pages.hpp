#pragma once
// Whether this build's operator new advises large blocks into transparent huge pages (huge_pages.cpp).
// Not under a sanitizer: its runtime brings an operator new of its own, which the linker takes before
// the one in our library, so the advice is left out there rather than half linked.

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define STIPPLE_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define STIPPLE_SANITIZER_ALLOCATOR 1
#endif
#endif

namespace stipple {

#if defined(STIPPLE_SANITIZER_ALLOCATOR)
inline constexpr bool kHugePageNew = false;
#else
inline constexpr bool kHugePageNew = true;
#endif

}  // namespace stipple
