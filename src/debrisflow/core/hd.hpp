#pragma once
// DF_HD marks functions callable from host code and, in a CUDA build, from device code.
#if defined(__CUDACC__)
#define DF_HD __host__ __device__
#define DF_INLINE __forceinline__
#else
#define DF_HD
#define DF_INLINE inline
#endif
