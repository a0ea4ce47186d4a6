#pragma once
// The most runs one command makes: a sweep's grid points times its seeds, or `opf run`'s,
// `opf reproduce`'s and `opf evaluate`'s seeds times their estimators (and experiments). A
// sweep's runs are expanded and checked in memory, and past it a mistyped count starts a run of
// years. Header-only: the tracking program reads it without linking the experiment drivers.

#include <cstddef>

namespace opf::experiments {

inline constexpr std::size_t kMaxRuns = 100000;

}  // namespace opf::experiments
