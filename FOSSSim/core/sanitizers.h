#pragma once

/// FOSSSIM_ADDRESS_SANITIZER is 1 in builds with AddressSanitizer, 0 otherwise. gcc says so with
/// __SANITIZE_ADDRESS__; clang 14 (the sanitize preset's compiler) only through __has_feature.
/// Code that must behave differently under the sanitizer (it replaces malloc and reserves
/// terabytes of address space, so memory limits and glibc's allocator options mean nothing
/// there) tests this macro, never the compilers' own spellings.
#if defined(__SANITIZE_ADDRESS__)
#define FOSSSIM_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FOSSSIM_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef FOSSSIM_ADDRESS_SANITIZER
#define FOSSSIM_ADDRESS_SANITIZER 0
#endif
