#pragma once
#include <cstddef>
#include <vector>

namespace debrisflow {

// Bytes a vector holds allocated (its capacity): what the memory reports in summary.json count.
template <class T> std::size_t bytes_of(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}
template <class T, class... More>
std::size_t bytes_of(const std::vector<T>& v, const More&... more) {
    return bytes_of(v) + bytes_of(more...);
}

} // namespace debrisflow
