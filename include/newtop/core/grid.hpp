#pragma once
/// \file
/// Points of an evenly spaced grid, computed so that the points a user writes in decimal come out
/// as those decimals: from 0 to 3 with 31 points the tenth is 0.9, not 0.8999999999999999.

#include <cstdint>

namespace newtop {

/// The k-th of n evenly spaced values from lo to hi (k = 0 gives lo, k = n − 1 gives hi; n = 1
/// gives lo). Each value is the double nearest to the exact point lo + k (hi − lo)/(n − 1), where
/// lo and hi stand for the shortest decimals that read back as them (as they were written in a
/// file or on the command line), whenever that exact point is a ratio of integers below 2⁵³;
/// otherwise (lo (n − 1 − k) + hi k)/(n − 1) in floating point, within an ulp or two of it. Never
/// accumulated: the same k gives the same bits in any order and on any thread.
double grid_value(double lo, double hi, std::int64_t n, std::int64_t k);

}  // namespace newtop
