#include "cuda_support.cuh"
#include "device_info.hpp"

namespace debrisflow::gpu {

std::string first_device() {
    int count = 0;
    if (const cudaError_t e = cudaGetDeviceCount(&count); e != cudaSuccess || count == 0)
        throw NoDevice(e != cudaSuccess ? cudaGetErrorString(e) : "no CUDA device");
    cudaDeviceProp prop{};
    check(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
    check(cudaSetDevice(0), "cudaSetDevice");
    check(cudaFree(nullptr), "CUDA context"); // created here, outside any timing
    return prop.name;
}

} // namespace debrisflow::gpu
