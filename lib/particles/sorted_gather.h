#pragma once
// The copy at the end of systematic resampling: slot k takes particle p_k, the running maximum of
// `marks` up to k (resampling_kernels.cpp's end marks), so p_k never decreases and advances by one
// slot per particle on average. Sixteen slots then almost always draw from a window of 32
// consecutive particles, and on a CPU with AVX-512 each row of such a block is two loads, one
// two-source permute and one store instead of sixteen scalar copies (the scalar copy was a
// quarter of a filter step). With AVX2 alone, float rows go in blocks of eight slots from windows
// of sixteen, each row two one-source permutes and a blend. Blocks whose window is wider fall back
// to the scalar copy.

#include <cstddef>
#include <cstdint>

namespace opf::kernels {

/// out row r, slot k = in row r, particle max(marks[0..k]) for k < count; `in` has `rows` rows of
/// n values, `out` rows of `count`. Every running maximum must be below n. Uses the permute path
/// when gather_uses_permutes().
void gather_by_running_maximum(const std::int32_t* marks, std::size_t count, const float* in,
                               std::size_t n, std::size_t rows, float* out);
void gather_by_running_maximum(const std::int32_t* marks, std::size_t count, const double* in,
                               std::size_t n, std::size_t rows, double* out);

/// Whether this build and CPU take the AVX-512 permute path (GCC on x86-64 with AVX-512F,
/// without OPF_NO_DISPATCH).
bool gather_uses_permutes();

/// Whether float rows take the AVX2 path instead (a CPU with AVX2 but not AVX-512F).
bool gather_uses_avx2();

/// The paths on their own, for the tests; the permute path requires gather_uses_permutes(), the
/// AVX2 path a CPU with AVX2.
void gather_by_running_maximum_scalar(const std::int32_t* marks, std::size_t count, const float* in,
                                      std::size_t n, std::size_t rows, float* out);
void gather_by_running_maximum_scalar(const std::int32_t* marks, std::size_t count,
                                      const double* in, std::size_t n, std::size_t rows,
                                      double* out);
void gather_by_running_maximum_permute(const std::int32_t* marks, std::size_t count,
                                       const float* in, std::size_t n, std::size_t rows,
                                       float* out);
void gather_by_running_maximum_permute(const std::int32_t* marks, std::size_t count,
                                       const double* in, std::size_t n, std::size_t rows,
                                       double* out);
void gather_by_running_maximum_avx2(const std::int32_t* marks, std::size_t count, const float* in,
                                    std::size_t n, std::size_t rows, float* out);

}  // namespace opf::kernels
