// newtop rotations SCENARIO.toml: the families of permanent rotations (docs/model.md §8), the
// Staude cone sampled to CSV with --out.

#include "newtop/analysis/rotations.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct RotationsArgs {
  std::string scenario;
  std::optional<std::string> out;
  int samples = 180;
  bool json = false;
};

void write_csv(io::AtomicFile& file, const RotationFamilies& f) {
  std::ostream& os = file.stream();
  os << "gamma1,gamma2,gamma3,omega_squared,admissible\n";
  for (const auto& c : f.cone) {
    os << format_number(c.gamma.x()) << ',' << format_number(c.gamma.y()) << ','
       << format_number(c.gamma.z()) << ',' << format_number(c.omega_squared) << ','
       << (c.admissible ? 1 : 0) << '\n';
  }
  file.commit();
}

io::Json rotations_json(const RotationFamilies& f) {
  io::Json axes = io::Json::array();
  for (const auto& a : f.principal_axes) axes.push_back(io::to_json(a));
  io::Json j;
  j["principal_axes_any_omega"] = axes;
  j["any_axis_omega"] = f.any_axis_omega ? io::Json(*f.any_axis_omega) : io::Json(nullptr);
  j["cone_is_whole_sphere"] = f.cone_is_whole_sphere;
  std::size_t admissible = 0;
  for (const auto& c : f.cone) admissible += c.admissible;
  j["cone_samples"] = f.cone.size();
  j["cone_admissible_samples"] = admissible;
  return j;
}

void print_rotations(std::ostream& os, const RotationFamilies& f, FieldKind kind) {
  os << "permanent rotations omega = Omega gamma (docs/model.md §8)\n";
  for (const auto& a : f.principal_axes) {
    os << "  principal axis gamma = " << format_vector(a) << ": any Omega\n";
  }
  if (f.any_axis_omega) {
    os << "  any axis: Omega = +-" << format_number(*f.any_axis_omega) << " (Omega^2 = lambda)\n";
  }
  if (f.cone_is_whole_sphere) {
    os << "  Staude cone: every axis, Omega^2 = lambda + M g (gamma x r0).(gamma x I gamma) / "
          "|gamma x I gamma|^2\n";
  } else if (!f.cone.empty()) {
    std::size_t admissible = 0;
    for (const auto& c : f.cone) admissible += c.admissible;
    os << (kind == FieldKind::quadratic ? "  Staude cone gamma.(I gamma x r0) = 0: "
                                        : "  axes with L(gamma) = Omega^2 gamma x I gamma: ")
       << f.cone.size() << " sampled axes, " << admissible << " admissible (Omega^2 >= 0)\n";
  }
}

int run(const RotationsArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  // The CSV is created (and checked against the inputs) before any work.
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) file = std::make_unique<io::AtomicFile>(*a.out, sc.input_files);
  const RotationFamilies f = permanent_rotations(sc.model, a.samples);
  if (file) write_csv(*file, f);
  if (a.json) {
    io::Json j = rotations_json(f);
    if (a.out) j["csv"] = *a.out;
    j["model"] = model_json(sc.model);
    j["field"] = field_json(sc.model);
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop rotations " << sc.source << "\n";
  print_model(std::cout, sc.model);
  print_rotations(std::cout, f, sc.model.kind());
  if (a.out) std::cout << "cone samples written to " << *a.out << "\n";
  return kExitOk;
}

const RegisterCommand reg_rotations{Command{
    "rotations", "Families of permanent rotations; the Staude cone of axes sampled to CSV",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<RotationsArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--out", a->out,
                     "write the sampled cone axes to this CSV file "
                     "(gamma1,gamma2,gamma3,omega_squared,admissible)");
      sub.add_option("--samples", a->samples, "samples per curve of the cone (default 180)");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
