// newtop chaos on an orbit scenario (docs/orbit.md §13): Lyapunov exponents, MEGNO and FLI from
// the orbit model's variational equations.

#include "newtop/orbit/orbit_chaos.hpp"

#include <iostream>
#include <memory>

#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/io/chaos_output.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "orbit_commands.hpp"
#include "orbit_summary.hpp"
#include "summary.hpp"

namespace newtop::app {

int orbit_chaos_command(const OrbitChaosArgs& a) {
  if (a.split) {
    throw InputError(
        "--split: the free body's split applies to the fixed-point model, not to an "
        "orbit scenario");
  }
  if (a.step) {
    throw InputError("--step: chaos on an orbit runs an embedded pair (--tol), not a fixed step");
  }
  const io::OrbitScenario sc = io::load_orbit_scenario(a.scenario);
  warn_units(sc);
  OrbitChaosSettings st;
  st.method = orbit_method(sc, a.method, std::nullopt, a.tol);
  st.t0 = sc.integrate.t0;
  st.t1 = orbit_t_end(sc, a.t_end);
  st.spectrum = a.spectrum;
  st.max_steps = sc.integrate.max_steps.value_or(100'000'000);
  st.on_step = throw_if_interrupted;
  check_orbit_chaos_settings(st);
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) {
    file = std::make_unique<io::AtomicFile>(*a.out);
    io::write_chaos_csv_header(file->stream(), a.spectrum);
    st.history = [&](const phase::ChaosSample& s) { io::write_chaos_csv_row(file->stream(), s); };
  }
  const InterruptGuard guard;
  OrbitChaosResult r;
  try {
    if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
      r = orbit_chaos(CircularOrbitModel(sc.body, *c), sc.initial, st);
    } else {
      r = orbit_chaos(EllipticOrbitModel(sc.body, std::get<EllipticOrbit>(sc.orbit)), sc.initial,
                      st);
    }
  } catch (const Interrupted& e) {
    std::cerr << "newtop: interrupted by " << signal_name(e.signal)
              << " at t = " << format_number(e.t)
              << (a.out ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
  if (file) file->commit();
  const phase::ChaosSample& c = r.indicators;
  if (a.json) {
    io::Json j;
    j["lyapunov_max"] = c.lyapunov_max;
    j["spectrum"] = c.spectrum ? io::Json(*c.spectrum) : io::Json(nullptr);
    j["megno"] = c.megno;
    j["fli"] = c.fli;
    j["t_end"] = r.t;
    j["method"] = st.method.name;
    j["step"] = nullptr;
    j["tol"] = st.method.abs_tol;
    j["outcome"] = to_string(r.outcome.status);
    j["flow"] = "forward";
    j["orbit"] = sc.circular() ? "circular" : "elliptic";
    print_json(std::cout, j);
  } else {
    std::cout << "lambda_max = " << format_number(c.lyapunov_max)
              << "   MEGNO <Y> = " << format_number(c.megno) << "   FLI = " << format_number(c.fli)
              << "\n";
    if (c.spectrum) {
      std::cout << "spectrum (the symplectic leaf):";
      for (double v : *c.spectrum) std::cout << ' ' << format_number(v);
      std::cout << '\n';
    }
    std::cout << "t = " << format_number(r.t) << " on "
              << (sc.circular() ? "a circular" : "an elliptic") << " orbit, method "
              << st.method.name << ", tol " << format_number(st.method.abs_tol) << ", outcome "
              << to_string(r.outcome.status) << '\n';
    if (a.out) std::cout << "history written to " << *a.out << '\n';
  }
  return r.outcome.status == Status::finished ? kExitOk : kExitIncomplete;
}

}  // namespace newtop::app
