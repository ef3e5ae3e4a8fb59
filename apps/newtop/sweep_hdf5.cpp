// HDF5 output of a sweep (docs/sweep.md): one dataset per column shaped like the grid, the swept
// axes as datasets, the sweep file and the base scenario as attributes. Written under a temporary
// name and renamed, so that an interrupted write never leaves a file at the destination; objects
// carry no modification times, so that the same results give the same bytes.

#include "sweep_hdf5.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#ifdef NEWTOP_WITH_HDF5
#include <hdf5.h>
#endif

namespace newtop::app {

using namespace newtop::sweep;

#ifdef NEWTOP_WITH_HDF5
namespace {

/// Closes an HDF5 handle with its own close function.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  Handle(hid_t i, herr_t (*c)(hid_t), const std::string& what) : id(i), close(c) {
    if (id < 0) throw InputError("--out: HDF5: cannot create " + what);
  }
  ~Handle() { close(id); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw InputError("--out: HDF5: cannot write " + what);
}

void write_doubles(hid_t where, const std::string& name, const std::vector<hsize_t>& shape,
                   const std::vector<double>& values, hid_t dcpl) {
  const Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr),
                     H5Sclose, name);
  const Handle set(
      H5Dcreate2(where, name.c_str(), H5T_IEEE_F64LE, space.id, H5P_DEFAULT, dcpl, H5P_DEFAULT),
      H5Dclose, name);
  check(H5Dwrite(set.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), name);
}

void write_strings(hid_t where, const std::string& name, const std::vector<hsize_t>& shape,
                   const std::vector<std::string>& values, hid_t dcpl) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose, name);
  check(H5Tset_size(type.id, H5T_VARIABLE), name);
  check(H5Tset_cset(type.id, H5T_CSET_UTF8), name);
  const Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr),
                     H5Sclose, name);
  const Handle set(
      H5Dcreate2(where, name.c_str(), type.id, space.id, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
      name);
  std::vector<const char*> text;
  for (const auto& v : values) text.push_back(v.c_str());
  check(H5Dwrite(set.id, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), name);
}

void write_attribute(hid_t where, const std::string& name, const std::string& value) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose, name);
  check(H5Tset_size(type.id, value.size() + 1), name);
  check(H5Tset_cset(type.id, H5T_CSET_UTF8), name);
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, name);
  const Handle attr(H5Acreate2(where, name.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT),
                    H5Aclose, name);
  check(H5Awrite(attr.id, type.id, value.c_str()), name);
}

void write_file(const std::string& path, const SweepFile& s, const SweepRun& run) {
  const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                    path);
  const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dataset properties");
  check(H5Pset_obj_track_times(dcpl.id, false), "dataset properties");
  std::vector<hsize_t> shape;
  if (s.combine == Combine::grid) {
    for (const Axis& a : s.axes) shape.push_back(a.values.size());
  }
  if (shape.empty()) shape.push_back(run.results.size());
  const Handle axes(H5Gcreate2(file.id, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                    "axes");
  for (const Axis& a : s.axes) write_doubles(axes.id, a.key, {a.values.size()}, a.values, dcpl.id);
  const std::vector<std::string> columns = quantity_columns(s);
  for (std::size_t k = 0; k < columns.size(); ++k) {
    std::vector<double> v;
    for (const PointResult& r : run.results) {
      v.push_back(r.status == "ok" ? r.values[k] : std::numeric_limits<double>::quiet_NaN());
    }
    write_doubles(file.id, columns[k], shape, v, dcpl.id);
  }
  std::vector<std::string> status;
  for (const PointResult& r : run.results) status.push_back(r.status);
  write_strings(file.id, "status", shape, status, dcpl.id);
  write_attribute(file.id, "sweep_file", s.source);
  write_attribute(file.id, "sweep", s.text);
  write_attribute(file.id, "scenario_file", s.base_source);
  write_attribute(file.id, "scenario", s.base_text);
  check(H5Fflush(file.id, H5F_SCOPE_GLOBAL), path);
}

}  // namespace

bool hdf5_available() { return true; }

void write_hdf5(const std::string& path, const SweepFile& s, const SweepRun& run) {
  const std::string tmp = path + ".tmp-" + std::to_string(std::hash<std::string>{}(path) % 100000);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become InputError, not library prints
  try {
    write_file(tmp, s, run);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError("--out: cannot rename the finished file to " + path + ": " + ec.message());
  }
}
#else
bool hdf5_available() { return false; }

void write_hdf5(const std::string&, const SweepFile&, const SweepRun&) {
  throw InputError(
      "--out: this build has no HDF5 (install libhdf5-dev and rebuild); give FILE.csv");
}
#endif

}  // namespace newtop::app
