#pragma once
// How a program that runs the filters should treat freed heap memory. A filter allocates its
// next generation of particles and its resampling buffers each step and frees the previous ones
// (so the filters of an ensemble reuse the same, cache-hot memory). glibc, by default, hands a
// freed block at the top of the heap back to the system and takes it again on the next step:
// about ten page faults per step for a lone filter at 5000 particles, 10% of its time. Programs
// call this once at start-up; it changes process-wide allocator settings, so the library never
// calls it itself.

namespace opf {

/// Keeps freed heap memory for reuse (glibc: trim threshold 256 MB, mmap threshold 32 MB, its
/// maximum). Returns false where the allocator has no such settings.
bool retain_freed_heap_memory();

}  // namespace opf
