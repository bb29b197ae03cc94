// Export macro for the shared core library. The library is built with hidden visibility, so
// only what carries SXK_API is part of the ABI that plug-ins and applications link against.
#pragma once

#if defined(_WIN32)
#if defined(SXK_BUILDING_CORE)
#define SXK_API __declspec(dllexport)
#else
#define SXK_API __declspec(dllimport)
#endif
#else
#define SXK_API __attribute__((visibility("default")))
#endif
