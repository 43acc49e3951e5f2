#pragma once
// HDF5 as Debian builds it (serial, without --enable-threadsafe) keeps its open files, error stack
// and type tables without a lock, and netCDF-C (Exodus II), the CGNS library and the MED reader all
// call it: every reader that reaches HDF5 holds this one lock, so that two of them never run in it
// at once (the Python module reads without the GIL).
#include <mutex>

namespace hbc::detail {

inline std::mutex& hdf5_library_lock() {
  static std::mutex lock;
  return lock;
}

}  // namespace hbc::detail
