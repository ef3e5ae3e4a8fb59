// What `newtop chaos` writes for a body (chaos_output.hpp).

#include "newtop/io/chaos_output.hpp"

#include <optional>
#include <string>

namespace newtop::io {
namespace {

bool is_adaptive(const MethodSettings& m) {
  return method_info(m.name).kind == MethodKind::adaptive;
}

/// The free-body split of a splitting method; none for the others.
std::optional<std::string> split_of(const MethodSettings& m) {
  if (method_info(m.name).kind != MethodKind::splitting) return std::nullopt;
  return std::string(to_string(free_body_split(m)));
}

}  // namespace

Json to_json(const phase::ChaosResult& r, const phase::ChaosRequest& request) {
  const phase::ChaosSample& c = r.indicators;
  const MethodSettings& m = request.method;
  const bool adaptive = is_adaptive(m);
  const std::optional<std::string> split = split_of(m);
  Json j;
  j["lyapunov_max"] = c.lyapunov_max;
  j["spectrum"] = c.spectrum ? Json(*c.spectrum) : Json(nullptr);
  j["megno"] = c.megno;
  j["fli"] = c.fli;
  j["t_end"] = r.outcome.t;
  j["method"] = m.name;
  j["step"] = adaptive ? Json(nullptr) : Json(m.step);
  if (adaptive) j["tol"] = m.abs_tol;
  if (split) j["split"] = *split;
  j["outcome"] = to_string(r.outcome.status);
  j["flow"] = request.t_end > request.t0 ? "forward" : "backward";
  return j;
}

void write_chaos_text(std::ostream& os, const phase::ChaosResult& r,
                      const phase::ChaosRequest& request) {
  const phase::ChaosSample& c = r.indicators;
  const MethodSettings& m = request.method;
  const bool adaptive = is_adaptive(m);
  const std::optional<std::string> split = split_of(m);
  os << "lambda_max = " << format_number(c.lyapunov_max)
     << "   MEGNO <Y> = " << format_number(c.megno) << "   FLI = " << format_number(c.fli) << "\n";
  if (c.spectrum) {
    os << "spectrum:";
    for (double v : *c.spectrum) os << ' ' << format_number(v);
    os << '\n';
  }
  os << "t = " << format_number(r.outcome.t)
     << (request.t_end < request.t0
             ? " (the backward flow from t0 = " + format_number(request.t0) + ")"
             : std::string())
     << ", method " << m.name << (adaptive ? ", tol " : ", step ")
     << format_number(adaptive ? m.abs_tol : m.step)
     << (split ? " (" + *split + " split)" : std::string()) << ", outcome "
     << to_string(r.outcome.status) << '\n';
}

void write_chaos_csv_header(std::ostream& os, bool spectrum) {
  os << "t,lyapunov_max,megno_y,megno,fli";
  if (spectrum) os << ",lambda1,lambda2,lambda3,lambda4,lambda5,lambda6";
  os << '\n';
}

void write_chaos_csv_row(std::ostream& os, const phase::ChaosSample& s) {
  os << format_number(s.t) << ',' << format_number(s.lyapunov_max) << ','
     << format_number(s.megno_y) << ',' << format_number(s.megno) << ',' << format_number(s.fli);
  if (s.spectrum) {
    for (double v : *s.spectrum) os << ',' << format_number(v);
  }
  os << '\n';
}

}  // namespace newtop::io
