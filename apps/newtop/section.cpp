// newtop section SCENARIO.toml --surface EXPR: Poincaré sections (docs/section.md).

#include "newtop/phase/section.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include "cli.hpp"
#include "command.hpp"
#include "integration_options.hpp"
#include "interrupt.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "orbit_commands.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct SectionArgs {
  std::string scenario, surface, direction = "up";
  IntegrationArgs integration;
  std::optional<std::int64_t> crossings;
  std::optional<int> orbits;
  std::optional<double> energy, area;
  std::optional<std::string> out;
  bool json = false;
};

/// The coordinates of a crossing on the section: Andoyer–Deprit, and for a plane γ_k = c the
/// momenta conjugate to the two other components of γ.
io::Json coords_json(const State& x, int plane_axis) {
  const phase::AndoyerDeprit ad = phase::andoyer_deprit(x);
  io::Json c;
  c["l"] = ad.l;
  c["L_over_G"] = ad.G > 0 ? ad.L / ad.G : 0.0;
  c["g"] = ad.g;
  c["G"] = ad.G;
  if (plane_axis >= 0) {
    const Vec3 p = phase::gamma_momentum(x);
    for (int d = 1; d <= 2; ++d) {
      const int i = (plane_axis + d) % 3;
      c["gamma" + std::to_string(i + 1)] = x.gamma[i];
      c["p_gamma" + std::to_string(i + 1)] = p[i];
    }
  }
  return c;
}

void write_csv(std::ostream& os, const std::vector<phase::Crossing>& cs, const Body& body,
               int plane_axis) {
  os << "orbit,t,p,q,r,gamma1,gamma2,gamma3,l,L_over_G,g,G";
  std::array<int, 2> other{(plane_axis + 1) % 3, (plane_axis + 2) % 3};
  if (plane_axis >= 0) {
    for (int i : other) os << ",p_gamma" << i + 1;
  }
  os << '\n';
  for (const phase::Crossing& c : cs) {
    const Vec3 w = omega(body, c.x);
    const phase::AndoyerDeprit ad = phase::andoyer_deprit(c.x);
    os << c.orbit << ',' << format_number(c.t);
    for (int i = 0; i < 3; ++i) os << ',' << format_number(w[i]);
    for (int i = 0; i < 3; ++i) os << ',' << format_number(c.x.gamma[i]);
    os << ',' << format_number(ad.l) << ',' << format_number(ad.G > 0 ? ad.L / ad.G : 0.0) << ','
       << format_number(ad.g) << ',' << format_number(ad.G);
    if (plane_axis >= 0) {
      const Vec3 p = phase::gamma_momentum(c.x);
      for (int i : other) os << ',' << format_number(p[i]);
    }
    os << '\n';
  }
}

/// --crossings without a t_end: the run stops at the crossings, or at this many steps per orbit
/// ([integrate] max_steps sets another cap; docs/section.md).
constexpr std::int64_t kCrossingsStepCap = 1'000'000;
constexpr std::int64_t kDefaultCrossings = 1000;

/// The request of each orbit: method, t0 and t_end as `simulate` resolves them; with --crossings
/// and no t_end anywhere, no t_end (the run stops at the crossings or at max_steps steps:
/// kCrossingsStepCap unless [integrate] max_steps).
phase::SectionRequest section_request(const io::Scenario& sc, const SectionArgs& a,
                                      const phase::Surface& surface, phase::Direction direction) {
  phase::SectionRequest q;
  q.surface = surface;
  q.direction = direction;
  q.max_crossings = a.crossings.value_or(kDefaultCrossings);
  q.start_on_surface = a.orbits.has_value();
  q.on_step = throw_if_interrupted;
  if (!a.crossings || a.integration.t_end || sc.integrate.t_end) {
    const RunSettings run = resolve_run(sc, a.integration);
    q.method = run.method;
    q.t0 = run.t0;
    q.t_end = run.t_end;
    q.options = run.options;
  } else {
    q.method = io::resolve_method(sc, a.integration.overrides());
    q.t0 = sc.integrate.t0;
    q.options.max_steps = sc.integrate.max_steps.value_or(kCrossingsStepCap);
  }
  return q;
}

/// The seeded orbits: how many, and why fewer than asked.
void print_seeded(std::ostream& os, const phase::Levels& levels, std::size_t seeded, int asked) {
  os << "orbits " << seeded << " seeded of " << asked << " asked";
  if (static_cast<int>(seeded) < asked) {
    os << ": at the other " << asked - static_cast<int>(seeded)
       << " seed points the level energy = " << format_number(levels.energy)
       << ", area = " << format_number(levels.area)
       << " does not meet the surface (the kinetic energy would be negative there)";
  }
  os << '\n';
}

/// The step cap of a run without t_end, and whether it was hit.
void print_cap(std::ostream& os, std::int64_t max_steps, std::int64_t crossings, int capped) {
  os << "no t_end: each orbit runs until " << crossings << " crossings, at most " << max_steps
     << " steps (the cap; [integrate] max_steps sets another)";
  if (capped > 0) os << "; the cap was hit on " << capped << " orbit(s) before their crossings";
  os << '\n';
}

int run(const SectionArgs& a) {
  // Every argument is checked before any work.
  const phase::Surface surface = phase::parse_surface(a.surface);
  const phase::Direction direction = phase::parse_direction(a.direction);
  if (io::is_orbit_scenario(a.scenario)) {
    if (a.orbits) {
      throw InputError(
          "--orbits: expected a body scenario, found an orbit scenario ([orbit]): seeded portraits "
          "on the Jacobi level are not available; run one scenario per start");
    }
    return orbit_section_command({a.scenario, a.surface, a.direction, a.integration.t_end,
                                  a.integration.step, a.integration.tol, a.integration.method,
                                  a.out, a.crossings.value_or(kDefaultCrossings), a.json});
  }
  phase::require_body_surface(surface);
  const io::Scenario sc = load_body_scenario(a.scenario);
  phase::SectionRequest request = section_request(sc, a, surface, direction);
  std::optional<phase::Levels> levels;
  std::vector<State> starts{sc.initial};
  if (a.orbits) {
    levels = phase::Levels{a.energy.value_or(energy(sc.model, sc.initial)),
                           a.area.value_or(area(sc.initial))};
    starts = phase::seed_orbits(sc.model, surface, *levels, *a.orbits, direction);
  }
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) file = std::make_unique<io::AtomicFile>(*a.out, sc.input_files);

  const InterruptGuard guard;
  std::vector<phase::Crossing> crossings;
  phase::IntegralsDrift drift;
  bool all_by_crossings = true;
  int capped = 0;  // orbits stopped by the cap of a run without t_end
  Status status = Status::finished;
  double residual = 0.0, relative = 0.0;
  try {
    for (std::size_t k = 0; k < starts.size(); ++k) {
      request.orbit = static_cast<int>(k);
      const phase::SectionResult r = phase::section(sc.model, starts[k], request);
      crossings.insert(crossings.end(), r.crossings.begin(), r.crossings.end());
      drift.merge(r.drift);  // each orbit against its own start
      const bool by_crossings = r.status == phase::SectionStatus::crossings;
      all_by_crossings = all_by_crossings && by_crossings;
      if (!request.t_end && !by_crossings) ++capped;
      if (r.outcome.status != Status::finished) status = r.outcome.status;
      residual = std::max(residual, r.max_residual);
      relative = std::max(relative, r.max_relative);
    }
  } catch (const Interrupted& e) {
    std::cerr << "newtop: interrupted by " << signal_name(e.signal)
              << " at t = " << format_number(e.t)
              << (a.out ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
  const int plane_axis = phase::gamma_plane_axis(surface);
  if (file) {
    write_csv(file->stream(), crossings, sc.model.body(), plane_axis);
    file->commit();
  }
  const bool empty = starts.empty();
  if (empty) {
    warn("the level energy = " + format_number(levels->energy) +
         ", area = " + format_number(levels->area) + " does not meet the surface '" + surface.text +
         "': no orbit");
  }
  const std::string stopped_by = all_by_crossings && !empty ? "crossings"
                                 : capped > 0               ? "cap"
                                                            : "t_end";
  if (a.json) {
    io::Json j;
    j["surface"] = surface.text;
    j["direction"] = phase::to_string(direction);
    io::Json list = io::Json::array();
    for (const phase::Crossing& c : crossings) {
      list.push_back({{"orbit", c.orbit},
                      {"t", c.t},
                      {"omega", io::to_json(omega(sc.model.body(), c.x))},
                      {"gamma", io::to_json(c.x.gamma)},
                      {"m", io::to_json(c.x.m)},
                      {"coords", coords_json(c.x, plane_axis)}});
    }
    j["crossings"] = list;
    j["count"] = crossings.size();
    j["stopped_by"] = stopped_by;
    j["max_surface_residual"] = residual;
    j["integrals_drift"] = drift.started ? io::to_json(drift.max_drift) : io::Json::object();
    j["method"] = request.method.name;
    j["outcome"] = to_string(status);
    if (levels) {
      j["levels"] = {{"energy", levels->energy},
                     {"area", levels->area},
                     {"orbits", starts.size()},
                     {"orbits_asked", *a.orbits},
                     {"empty", empty}};
    }
    if (!request.t_end) {
      j["cap"] = {
          {"max_steps", request.options.max_steps}, {"hit", capped > 0}, {"orbits_capped", capped}};
    }
    print_json(std::cout, j);
  } else {
    std::cout << "surface " << surface.text << " (" << phase::to_string(direction)
              << "): " << crossings.size() << " crossings of " << starts.size()
              << " orbit(s), stopped by " << stopped_by
              << "\nmax |g| at the crossings = " << format_number(residual) << " ("
              << format_number(relative) << " of the size of its terms)\nmethod "
              << request.method.name << ", outcome " << to_string(status) << '\n';
    if (levels) print_seeded(std::cout, *levels, starts.size(), *a.orbits);
    if (!request.t_end) {
      print_cap(std::cout, request.options.max_steps, request.max_crossings, capped);
    }
    if (a.out) std::cout << "crossings written to " << *a.out << '\n';
  }
  return status == Status::finished ? kExitOk : kExitIncomplete;
}

const RegisterCommand reg_section{Command{
    "section",
    "Poincare section: the crossings of the trajectory with a surface g(omega, gamma[, normal]) = "
    "0",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<SectionArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--surface", a->surface,
                     "affine surface, e.g. 'gamma3 = 0' or 'gamma1 + 0.5*gamma2 = 0.1' "
                     "(omega1..3, m1..3, gamma1..3; normal1..3 on an orbit scenario)")
          ->required();
      sub.add_option("--direction", a->direction, "up (default), down or both");
      sub.add_option("--crossings", a->crossings,
                     "stop after N crossings per orbit (default 1000); without a t_end, run "
                     "until them (at most 10^6 steps per orbit, docs/section.md)");
      auto* orbits = sub.add_option("--orbits", a->orbits,
                                    "phase portrait: K orbits seeded on the surface, on the "
                                    "scenario's energy and area levels (docs/section.md; body "
                                    "scenarios only)");
      sub.add_option("--energy", a->energy, "energy level of the seeded orbits")->needs(orbits);
      sub.add_option("--area", a->area, "area level m.gamma of the seeded orbits")->needs(orbits);
      add_integration_options(sub, a->integration);
      sub.add_option("--out", a->out, "write the crossings to this CSV file");
      sub.add_flag("--json", a->json, "print one JSON object instead of the summary");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
