// newtop section on an orbit scenario (docs/section.md "Orbit scenarios"): the crossings of
// (m, γ, n) with a surface that may name the orbit normal, with coordinates in the orbital frame.

#include "newtop/orbit/orbit_section.hpp"

#include <iostream>
#include <memory>

#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "orbit_commands.hpp"
#include "orbit_summary.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

/// A crossing as reported: the time, ν on an ellipse, the state, the orbital-frame coordinates.
struct Row {
  const OrbitCrossing& c;
  double t;
  OrbitFrameCoords coords;
};

Row row(const io::OrbitScenario& sc, const OrbitCrossing& c) {
  const double rate = sc.circular() ? std::get<CircularOrbit>(sc.orbit).rate
                                    : anomaly_rate(std::get<EllipticOrbit>(sc.orbit), c.t);
  return {c, orbit_time(sc, c.t, sc.integrate.t0), orbit_frame_coords(sc.body, c.x, rate)};
}

void write_csv(std::ostream& os, const io::OrbitScenario& sc,
               const std::vector<OrbitCrossing>& cs) {
  os << "orbit,t," << (sc.circular() ? "" : "nu,")
     << "p,q,r,gamma1,gamma2,gamma3,normal1,normal2,normal3,psi,theta,phi,"
        "omega_rel1,omega_rel2,omega_rel3,roll,pitch,yaw\n";
  for (const OrbitCrossing& c : cs) {
    const Row r = row(sc, c);
    os << c.orbit << ',' << format_number(r.t);
    if (!sc.circular()) os << ',' << format_number(c.t);
    auto put = [&](const Vec3& v) {
      for (int i = 0; i < 3; ++i) os << ',' << format_number(v[i]);
    };
    put(omega(sc.body, c.x));
    put(c.x.gamma);
    put(c.x.normal);
    put(r.coords.euler_321);
    put(r.coords.omega_relative);
    put(roll_pitch_yaw(lvlh_to_body(c.x)));
    os << '\n';
  }
}

io::Json drift_json(const OrbitSectionDrift& d) {
  io::Json j = io::Json::object();
  if (!d.started) return j;
  if (d.has_jacobi) j["jacobi"] = d.jacobi;
  j["gamma_gamma"] = d.gamma_gamma;
  j["normal_normal"] = d.normal_normal;
  j["gamma_normal"] = d.gamma_normal;
  return j;
}

}  // namespace

int orbit_section_command(const OrbitSectionArgs& a) {
  // Every argument is checked before any work.
  const phase::Surface surface = phase::parse_surface(a.surface);
  const phase::Direction direction = phase::parse_direction(a.direction);
  const io::OrbitScenario sc = io::load_orbit_scenario(a.scenario);
  warn_units(sc);
  phase::SectionRequest request;
  request.method = orbit_method(sc, a.method, a.step, a.tol);
  request.surface = surface;
  request.direction = direction;
  request.max_crossings = a.crossings;
  request.t0 = sc.integrate.t0;
  request.t_end = orbit_t_end(sc, a.t_end);
  request.options.max_steps = sc.integrate.max_steps.value_or(100'000'000);
  request.on_step = throw_if_interrupted;
  const phase::SurfaceFunction g(surface, sc.body, /*with_normal=*/true);  // checks the surface
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) file = std::make_unique<io::AtomicFile>(*a.out);

  const InterruptGuard guard;
  OrbitSectionResult r;
  try {
    if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
      r = orbit_section(CircularOrbitModel(sc.body, *c), sc.initial, request);
    } else {
      r = orbit_section(EllipticOrbitModel(sc.body, std::get<EllipticOrbit>(sc.orbit)), sc.initial,
                        request);
    }
  } catch (const Interrupted& e) {
    // The independent variable: t on a circular orbit, the true anomaly on an ellipse.
    const bool circular = std::holds_alternative<CircularOrbit>(sc.orbit);
    std::cerr << "newtop: interrupted by " << signal_name(e.signal) << " at "
              << (circular ? "t = " : "nu = ") << format_number(e.t)
              << (a.out ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
  if (file) {
    write_csv(file->stream(), sc, r.crossings);
    file->commit();
  }
  const MethodSettings& method = request.method;
  const std::vector<OrbitCrossing>& crossings = r.crossings;
  const Status status = r.outcome;
  const std::string stopped_by =
      r.status == phase::SectionStatus::crossings ? "crossings" : "t_end";
  if (a.json) {
    io::Json j;
    j["surface"] = surface.text;
    j["direction"] = phase::to_string(direction);
    io::Json list = io::Json::array();
    for (const OrbitCrossing& c : crossings) {
      const Row w = row(sc, c);
      io::Json e = {{"orbit", c.orbit},
                    {"t", w.t},
                    {"omega", io::to_json(omega(sc.body, c.x))},
                    {"gamma", io::to_json(c.x.gamma)},
                    {"m", io::to_json(c.x.m)},
                    {"normal", io::to_json(c.x.normal)},
                    {"coords",
                     {{"euler_321", io::to_json(w.coords.euler_321)},
                      {"omega_relative", io::to_json(w.coords.omega_relative)},
                      {"roll_pitch_yaw", io::to_json(roll_pitch_yaw(lvlh_to_body(c.x)))},
                      {"lvlh_quaternion", scalar_first(lvlh_quaternion(lvlh_to_body(c.x)))}}}};
      if (!sc.circular()) e["nu"] = c.t;
      list.push_back(e);
    }
    j["crossings"] = list;
    j["count"] = crossings.size();
    j["stopped_by"] = stopped_by;
    j["max_surface_residual"] = r.max_residual;
    j["integrals_drift"] = drift_json(r.drift);
    j["method"] = method.name;
    j["outcome"] = to_string(status);
    j["orbit"] = sc.circular() ? "circular" : "elliptic";
    print_json(std::cout, j);
  } else {
    std::cout << "surface " << surface.text << " (" << phase::to_string(direction)
              << "): " << crossings.size() << " crossings on a "
              << (sc.circular() ? "circular" : "elliptic") << " orbit, stopped by " << stopped_by
              << "\nmax |g| at the crossings = " << format_number(r.max_residual) << " ("
              << format_number(r.max_relative) << " of the size of its terms)\nmethod "
              << method.name << ", outcome " << to_string(status) << '\n';
    if (a.out) std::cout << "crossings written to " << *a.out << '\n';
  }
  return status == Status::finished ? kExitOk : kExitIncomplete;
}

}  // namespace newtop::app
