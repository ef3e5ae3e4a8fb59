// newtop libration SCENARIO.toml: planar pitch motion on an elliptic orbit (Beletsky's equation,
// docs/orbit.md §9): the p:q spin–orbit resonances as periodic solutions with their Floquet
// multipliers, and the periapsis section with a finite-time Lyapunov exponent per start.

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>

#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/spin_orbit.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

constexpr double kPlanarTolerance = 1e-9;  // of the scenario's initial state, as read

struct LibrationArgs {
  std::string scenario;
  std::string resonances = "1:2,1:1,3:2,2:1,5:2";
  std::optional<std::string> spin, out;
  int iterates = 200;
  bool asymmetric = false;
  bool json = false;
};

io::Json solution_json(const PeriodicSolution& s, double e) {
  io::Json m = io::Json::array();
  for (const auto& z : s.multipliers) m.push_back({z.real(), z.imag()});
  return {{"theta0", s.theta0},
          {"dtheta0", s.dtheta0},
          {"spin0", spin_from_dtheta(e, s.dtheta0)},
          {"multipliers", m},
          {"trace", s.monodromy.trace()},
          {"stability", to_string(s.stability)},
          {"residual", s.residual},
          {"max_deviation", s.max_deviation},
          {"symmetry_distance", s.symmetry_distance},
          {"symmetric", s.symmetry_distance <= kSymmetryTolerance}};
}

// A circular Kepler orbit is the ellipse e = 0, its true anomaly counted from the start; a forced
// one (λ ≠ 3ω0²) is no Kepler orbit and has no Beletsky equation.
EllipticOrbit pitch_orbit(const io::OrbitScenario& sc) {
  if (const auto* e = std::get_if<EllipticOrbit>(&sc.orbit)) return *e;
  const auto& c = std::get<CircularOrbit>(sc.orbit);
  if (!(c.rate > 0) || c.lambda_ != 3.0 * c.rate * c.rate) {
    throw InputError(sc.source + ": [orbit]: expected a Kepler orbit (lambda = 3 rate^2) for " +
                     "newtop libration, found rate " + format_number(c.rate) + " and lambda " +
                     format_number(c.lambda_));
  }
  return EllipticOrbit::from_mean_motion(c.rate, 0.0, 0.0);
}

int run_guarded(const LibrationArgs& a) {
  const io::OrbitScenario sc = io::load_orbit_scenario(a.scenario);
  const EllipticOrbit orbit = pitch_orbit(sc);
  // The pitch axis is the principal axis along the orbit normal, whichever it is.
  const PitchFrame frame = pitch_frame(sc.body, sc.initial);
  const PitchProblem problem = pitch_problem(frame.body, orbit);
  const std::vector<SpinOrbitResonance> resonances = io::parse_resonances(a.resonances);
  if (a.iterates < 1 || a.iterates > 100000) {
    throw InputError("--iterates: expected 1 to 100000, found " + std::to_string(a.iterates));
  }
  const std::optional<io::SpinScan> scan =
      a.spin ? std::optional(io::parse_spin(*a.spin)) : std::nullopt;
  // The scenario's start, carried to the first periapsis ν = 2πj ≥ ν0.
  const double nu0 = orbit.true_anomaly0;
  const double periapsis = 2 * std::numbers::pi * std::ceil(nu0 / (2 * std::numbers::pi));
  const Vec2 x0 = pitch_advance(
      problem, pitch_state(frame.body, orbit, frame.state, nu0, kPlanarTolerance), nu0, periapsis);
  std::vector<Vec2> starts{x0};
  if (scan) {
    for (int i = 0; i < scan->n; ++i) {
      const double s =
          scan->n == 1 ? scan->lo : scan->lo + (scan->hi - scan->lo) * i / (scan->n - 1);
      starts.emplace_back(0.0, dtheta_from_spin(problem.eccentricity, s));
    }
  }
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) {
    const std::string inputs[] = {a.scenario};
    file = std::make_unique<io::AtomicFile>(*a.out, inputs);
    file->stream() << "start,orbit,theta,dtheta,spin,lyapunov,chaotic\n";
  }

  const double e = problem.eccentricity;
  io::Json res = io::Json::array();
  for (const SpinOrbitResonance& r : resonances) {
    const double ratio = double(r.p) / r.q;
    io::Json sols = io::Json::array();
    throw_if_interrupted(0.0);
    for (const PeriodicSolution& s : periodic_solutions(problem, r))
      sols.push_back(solution_json(s, e));
    io::Json entry{{"resonance", std::to_string(r.p) + ":" + std::to_string(r.q)},
                   {"spin_ratio", ratio},
                   {"periods", r.periods},
                   {"half_turns", r.half_turns},
                   {"strength", resonance_strength(ratio, e)},
                   {"averaged_half_width", averaged_half_width(problem, ratio)},
                   {"solutions", sols}};
    if (a.asymmetric) {
      io::Json asym = io::Json::array();
      for (const PeriodicSolution& s : shoot_periodic_solutions(problem, r)) {
        if (s.symmetry_distance > kSymmetryTolerance) asym.push_back(solution_json(s, e));
      }
      entry["asymmetric_solutions"] = asym;
    }
    res.push_back(entry);
  }
  io::Json section = io::Json::array();
  int chaotic = 0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    throw_if_interrupted(0.0);
    const SectionOrbit o = periapsis_section(problem, starts[i][0], starts[i][1], a.iterates);
    chaotic += o.chaotic;
    if (file) {
      for (std::size_t j = 0; j < o.points.size(); ++j) {
        const Vec2& x = o.points[j];
        file->stream() << i << ',' << j + 1 << ',' << format_number(x[0]) << ','
                       << format_number(x[1]) << ',' << format_number(spin_from_dtheta(e, x[1]))
                       << ',' << format_number(o.lyapunov) << ',' << (o.chaotic ? 1 : 0) << '\n';
      }
    }
    section.push_back({{"start", i},
                       {"theta0", o.theta0},
                       {"dtheta0", o.dtheta0},
                       {"spin0", spin_from_dtheta(e, o.dtheta0)},
                       {"lyapunov", o.lyapunov},
                       {"chaotic", o.chaotic}});
  }
  if (file) file->commit();
  io::Json j{{"scenario", sc.source},
             {"eccentricity", e},
             {"k", problem.k},
             {"iterates", a.iterates},
             {"chaos_threshold", chaos_threshold(a.iterates)},
             {"resonances", res},
             {"starts", section},
             {"chaotic_starts", chaotic}};
  if (a.out) j["csv"] = *a.out;
  if (a.json) {
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop libration " << sc.source << "\n  e = " << format_number(e)
            << ", k = (B - A)/C = " << format_number(problem.k) << "\n";
  for (const auto& r : j["resonances"]) {
    std::cout << "resonance " << r["resonance"].get<std::string>()
              << "  H = " << format_number(r["strength"].get<double>()) << ", averaged half-width "
              << format_number(r["averaged_half_width"].get<double>()) << "\n";
    for (const auto& s : r["solutions"]) {
      std::cout << "  theta(0) = " << format_number(s["theta0"].get<double>())
                << "  theta'(0) = " << format_number(s["dtheta0"].get<double>())
                << "  trace = " << format_number(s["trace"].get<double>()) << "  "
                << s["stability"].get<std::string>() << "\n";
    }
    for (const auto& s : r.value("asymmetric_solutions", io::Json::array())) {
      std::cout << "  asymmetric: theta(0) = " << format_number(s["theta0"].get<double>())
                << "  theta'(0) = " << format_number(s["dtheta0"].get<double>())
                << "  trace = " << format_number(s["trace"].get<double>()) << "  "
                << s["stability"].get<std::string>() << "\n";
    }
  }
  std::cout << starts.size() << " starts, " << a.iterates << " orbits each: " << chaotic
            << " chaotic (Lyapunov exponent > " << format_number(chaos_threshold(a.iterates))
            << " per orbit)\n";
  if (a.out) std::cout << "section written to " << *a.out << "\n";
  return kExitOk;
}

/// SIGINT/SIGTERM between resonances or starts: the CSV under construction is removed, exit
/// 128 + the signal.
int run(const LibrationArgs& a) {
  const InterruptGuard guard;
  try {
    return run_guarded(a);
  } catch (const Interrupted& e) {
    std::cerr << "newtop: interrupted by " << signal_name(e.signal)
              << (a.out ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
}

const RegisterCommand reg{Command{
    "libration",
    "Planar pitch on an elliptic orbit: spin-orbit resonances, Floquet multipliers, periapsis "
    "section",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<LibrationArgs>();
      sub.add_option("scenario", a->scenario,
                     "orbit scenario file (TOML), elliptic (or circular, as e = 0)")
          ->required();
      sub.add_option("--resonances", a->resonances,
                     "p:q list (spin:orbit), default " + a->resonances);
      sub.add_option("--spin", a->spin,
                     "LO:HI:N section starts at periapsis, theta = 0, spin rate in units of n");
      sub.add_option("--iterates", a->iterates, "orbits per start (default 200)");
      sub.add_flag("--asymmetric", a->asymmetric,
                   "also find periodic solutions without the symmetry assumption (2-D shooting "
                   "from a 12 x 12 grid of starts)");
      sub.add_option("--out", a->out, "section CSV file");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
