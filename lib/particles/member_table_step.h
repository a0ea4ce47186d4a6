#pragma once
// The multiple-model particle step, x_i += offset[m_i] + spread[m_i] * noise_i: each particle
// moved by its own motion model's entries of two small tables (mixture_particle_motion.h).
// Reading a table at a per-particle index is a gather, which GCC leaves scalar here (gathers are
// slow on several CPUs). On a CPU with AVX-512 a table of up to 32 members instead sits in four
// registers and is read with two-source permutes, eight particles at a time. The permute path
// computes x_i + fma(spread, noise_i, offset), as GCC compiles the generic loop at -O3 for a CPU
// with fused multiply-adds: a release build's seeded results are the same on either path.

#include <array>
#include <cstddef>
#include <cstdint>

namespace opf::kernels {

/// One value per motion-model member, indexed by a particle's member (a byte), so that every
/// byte reads inside it; the entries past the members' are zero.
using MemberTable = std::array<double, 256>;

/// x[i] += offset[member[i]] + spread[member[i]] * noise[i] for i < count, for `members` members
/// (each member[i] below it). Uses the permute path when member_step_uses_permutes(members).
void add_member_offset_and_noise(double* x, const float* noise, const std::uint8_t* member,
                                 const MemberTable& offset, const MemberTable& spread,
                                 std::size_t members, std::size_t count);

/// The largest table the permute path holds in registers.
inline constexpr std::size_t kPermuteTableSize = 32;

/// Whether this build and CPU take the permute path for tables of `members` entries (GCC on
/// x86-64 with AVX-512F, without OPF_NO_DISPATCH, and at most kPermuteTableSize members).
bool member_step_uses_permutes(std::size_t members);

/// The paths on their own, for the tests; the permute path requires
/// member_step_uses_permutes(members).
void add_member_offset_and_noise_generic(double* x, const float* noise, const std::uint8_t* member,
                                         const MemberTable& offset, const MemberTable& spread,
                                         std::size_t count);
void add_member_offset_and_noise_permute(double* x, const float* noise, const std::uint8_t* member,
                                         const MemberTable& offset, const MemberTable& spread,
                                         std::size_t members, std::size_t count);

}  // namespace opf::kernels
