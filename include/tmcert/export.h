// TMCERT_API marks what the shared library exports.  The library is built
// with hidden visibility, so everything else in it (the internals under
// src/ and kernels/, CGAL's and GMP's instantiations) stays private.
#pragma once

#if defined(_WIN32)
#  if defined(TMCERT_BUILDING_SHARED)
#    define TMCERT_API __declspec(dllexport)
#  elif defined(TMCERT_USING_SHARED)
#    define TMCERT_API __declspec(dllimport)
#  else
#    define TMCERT_API
#  endif
#else
#  define TMCERT_API __attribute__((visibility("default")))
#endif
