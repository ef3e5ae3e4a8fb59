#include "newtop/io/output.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>

#include "newtop/io/json.hpp"

namespace newtop::io {

namespace {

namespace fs = std::filesystem;

void check_output_path(const std::string& path, std::span<const std::string> inputs) {
  if (path.empty()) throw InputError("output file: expected a file name, found an empty name");
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::is_directory(st) || path.back() == '/') {
    throw InputError(path + ": expected an output file name, found a directory");
  }
  if (fs::exists(st) && !fs::is_regular_file(st)) {
    throw InputError(path +
                     ": expected an output file name, found an existing file that is not a "
                     "regular file (a device or a pipe would be replaced)");
  }
  for (const std::string& in : inputs) {
    if (fs::exists(st) && fs::equivalent(path, in, ec)) {
      throw InputError(path + ": expected an output file, found the input file " + in +
                       " (it would be overwritten)");
    }
  }
}

// The temporaries of the open AtomicFiles, for a signal handler to remove: a fixed table of
// lock-free slots (no allocation, no lock: async-signal-safe to read). A file that finds no free
// slot is still removed by its destructor on every normal or exceptional exit.
std::array<std::atomic<const char*>, 32> open_temporaries{};

static_assert(std::atomic<const char*>::is_always_lock_free);

void enlist(const char* tmp) {
  for (auto& slot : open_temporaries) {
    const char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, tmp)) return;
  }
}

void delist(const char* tmp) {
  for (auto& slot : open_temporaries) {
    const char* expected = tmp;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

}  // namespace

void remove_open_temporaries() noexcept {
  for (auto& slot : open_temporaries) {
    if (const char* tmp = slot.load()) ::unlink(tmp);
  }
}

AtomicFile::AtomicFile(std::string path, std::span<const std::string> inputs)
    : path_(std::move(path)), tmp_(path_ + ".partial-" + std::to_string(::getpid())) {
  check_output_path(path_, inputs);
  enlist(tmp_.c_str());  // before the file exists: a signal from its creation on removes it
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    delist(tmp_.c_str());
    throw InputError(path_ + ": cannot open the output file for writing");
  }
}

AtomicFile::~AtomicFile() {
  delist(tmp_.c_str());
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw InputError(path_ + ": write failed (disk full or file unwritable)");
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  if (ec) throw InputError(path_ + ": cannot move the output into place: " + ec.message());
  committed_ = true;
  delist(tmp_.c_str());  // after the rename: a signal in between finds no file to remove
}

CsvTrajectory::CsvTrajectory(std::ostream& out, const Model& model, AttitudeColumns attitude)
    : out_(out), model_(model), attitude_(attitude) {
  const IntegralValues v = integrals(model, State{});
  brun_ = v.brun.has_value();
  lagrange_ = v.lagrange.has_value();
  out_ << "t,p,q,r,gamma1,gamma2,gamma3,energy,area,geometric";
  if (brun_) out_ << ",brun";
  if (lagrange_) out_ << ",lagrange";
  if (attitude_.quaternion) out_ << ",q0,q1,q2,q3";
  if (attitude_.euler == 321) out_ << ",euler321_psi,euler321_theta,euler321_phi";
  if (attitude_.euler == 313) out_ << ",euler313_phi,euler313_theta,euler313_psi";
  out_ << '\n';
}

void CsvTrajectory::write(double t, const State& s) {
  append(t, s);
  line_ += '\n';
  out_ << line_;
}

void CsvTrajectory::write(double t, const OrientedState& s) {
  append(t, s);
  auto add = [&](double x) { line_ += ',' + format_number(x); };
  if (attitude_.quaternion) {
    for (const double c : scalar_first(s.q)) add(c);
  }
  if (attitude_.euler != 0) {
    const Vec3 a = attitude_.euler == 321 ? euler_321(s.q) : euler_313(s.q);
    for (int i = 0; i < 3; ++i) add(a[i]);
  }
  line_ += '\n';
  out_ << line_;
}

void CsvTrajectory::append(double t, const State& s) {
  const Vec3 w = omega(model_.body(), s);
  const IntegralValues v = integrals(model_, s);
  line_.clear();
  auto add = [&](double x) {
    if (!line_.empty()) line_ += ',';
    line_ += format_number(x);
  };
  add(t);
  for (int i = 0; i < 3; ++i) add(w[i]);
  for (int i = 0; i < 3; ++i) add(s.gamma[i]);
  add(v.energy);
  add(v.area);
  add(v.geometric);
  if (brun_) add(*v.brun);
  if (lagrange_) add(*v.lagrange);
}

Json to_json(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json to_json(const IntegralValues& v) {
  Json j;
  j["energy"] = v.energy;
  j["area"] = v.area;
  j["geometric"] = v.geometric;
  if (v.brun) j["brun"] = *v.brun;
  if (v.lagrange) j["lagrange"] = *v.lagrange;
  return j;
}

}  // namespace newtop::io
