#pragma once
// DF_HD marks functions callable from host code and, in a CUDA build, from device code.
#if defined(__CUDACC__)
#define DF_HD __host__ __device__
#define DF_INLINE __forceinline__
#else
#define DF_HD
#define DF_INLINE inline
#endif
// DF_HOT_INLINE: a small function on a particle-pair hot path that the host compiler must
// inline (GCC's size heuristics otherwise leave the DEM contact law as a call per contact).
#if defined(__CUDACC__)
#define DF_HOT_INLINE __forceinline__
#elif defined(__GNUC__)
#define DF_HOT_INLINE inline __attribute__((always_inline))
#else
#define DF_HOT_INLINE inline
#endif
