#pragma once
/// \file
/// Output writers: files that appear whole or not at all, CSV trajectories (JSON: json.hpp).

#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "newtop/model/attitude.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop::io {

/// A file written under a temporary name beside its destination and renamed over it by commit();
/// destroyed without commit() it removes the temporary, so no half-written file is ever left.
///
/// Every open AtomicFile's temporary is listed where a signal handler can find it:
/// remove_open_temporaries() removes them (async-signal-safe), for a process about to die of a
/// signal that does not unwind its stack.
class AtomicFile {
 public:
  /// Opens the temporary at once, so that an output that cannot be created is found before any
  /// work: throws InputError for an empty name, a name that is a directory or an existing file
  /// that is not a regular file (a device, a FIFO), a name that is one of `inputs` (the same file
  /// under any name), and a folder where the temporary cannot be created.
  explicit AtomicFile(std::string path, std::span<const std::string> inputs = {});
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes, checks for write errors and renames into place; throws InputError on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Removes the temporary of every AtomicFile still open (not committed). Async-signal-safe: for a
/// SIGINT/SIGTERM handler before the process terminates.
void remove_open_temporaries() noexcept;

/// The attitude columns of a CSV trajectory.
struct AttitudeColumns {
  /// q0,q1,q2,q3: the attitude quaternion (body → inertial), scalar first.
  bool quaternion = false;
  /// 0 for none; 321: euler321_psi,euler321_theta,euler321_phi; 313:
  /// euler313_phi,euler313_theta,euler313_psi (radians, newtop/model/attitude.hpp).
  int euler = 0;
};

/// CSV trajectory: `t,p,q,r,gamma1,gamma2,gamma3,energy,area,geometric[,brun][,lagrange]`, then
/// the attitude columns asked for, numbers in shortest round-trip form; the integrals are those of
/// the model's own field (integrals(Model, s)), brun and lagrange only where they hold.
class CsvTrajectory {
 public:
  CsvTrajectory(std::ostream& out, const Model& model, AttitudeColumns attitude = {});
  void write(double t, const State& s);
  /// A row with the attitude columns (of s.q).
  void write(double t, const OrientedState& s);

 private:
  void append(double t, const State& s);
  std::ostream& out_;
  const Model& model_;
  bool brun_ = false, lagrange_ = false;
  AttitudeColumns attitude_;
  std::string line_;
};

}  // namespace newtop::io
