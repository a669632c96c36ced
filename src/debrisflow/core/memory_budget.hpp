#pragma once
#include <cstddef>
#include <string>

namespace debrisflow {

// The memory a case may ask for before anything is allocated: the machine's physical memory,
// or what `--max-memory` sets. Checked by the resource estimate (scenario/resource_estimate)
// and by every builder whose size comes from the input (lattices, meshes, cell grids).
double memory_budget_bytes();
void set_memory_budget_bytes(double bytes);

// The process's resident memory now (Linux: /proc/self/statm), 0 where it cannot be read.
double resident_bytes();

// Throws OutOfMemoryError, naming `what`, where allocating `bytes` more would take the process
// beyond the budget (an overcommitting system would otherwise kill it when the pages are
// touched, without a message).
void require_memory(double bytes, const std::string& what);

// "512 MiB", "3.2 GiB", "1.4e+03 TiB"
std::string format_bytes(double bytes);

// Parses "4G", "512M", "1.5GiB", "2e9" (bytes; K/M/G/T are binary); throws InputError.
double parse_bytes(const std::string& text);

} // namespace debrisflow
