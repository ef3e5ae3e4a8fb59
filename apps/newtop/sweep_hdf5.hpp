#pragma once
// HDF5 output of newtop sweep (sweep_hdf5.cpp; libhdf5 when the build found it).

#include <string>

#include "newtop/sweep/sweep.hpp"

namespace newtop::app {

/// Whether this build writes HDF5 (libhdf5 found at configure time).
bool hdf5_available();

/// Writes the results as HDF5 (docs/sweep.md): a dataset per column shaped like the grid (NaN where
/// the point failed, and `status` says why), `axes/KEY` for each swept key, and the sweep file and
/// the base scenario as attributes. Written under a temporary name and renamed into place. Throws
/// InputError when it cannot be written or the build has no HDF5.
void write_hdf5(const std::string& path, const sweep::SweepFile& s, const sweep::SweepRun& run);

}  // namespace newtop::app
