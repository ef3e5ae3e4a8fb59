// newtop continue: the family, its events and boundaries as CSV, JSON and a text summary
// (docs/continuation.md §5).

#include <iostream>

#include "command.hpp"
#include "continue.hpp"
#include "newtop/io/json.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

io::Json point_json(const FamilyPoint& p, const std::vector<std::string>& names) {
  io::Json values = io::Json::object(), mult = io::Json::array();
  for (std::size_t k = 0; k < names.size(); ++k) values[names[k]] = p.values[k];
  for (const auto& z : p.multipliers) mult.push_back({z.real(), z.imag()});
  return {{"parameter", p.parameter},
          {"values", values},
          {"period", p.period},
          {"multipliers", mult},
          {"stability", p.stability}};
}

void write_boundaries_csv(std::ostream& o, const Run& r, const ContinueArgs& a) {
  o << "curve,type," << *a.second << ',' << a.parameter << ",theta0,dtheta0,stability\n";
  for (std::size_t i = 0; i < r.boundaries.size(); ++i) {
    for (const FamilyPoint& p : r.boundaries[i].points) {
      o << i << ',' << to_string(r.boundaries[i].type) << ',' << format_number(p.parameter) << ','
        << format_number(p.values[2]) << ',' << format_number(p.values[0]) << ','
        << format_number(p.values[1]) << ',' << p.stability << '\n';
    }
  }
}

void write_csv(std::ostream& o, const Run& r) {
  o << "parameter";
  for (const auto& n : r.names) o << ',' << n;
  o << ",period";
  const std::size_t m = r.family.points.empty() ? 0 : r.family.points[0].multipliers.size();
  for (std::size_t k = 1; k <= m; ++k) o << ",multiplier" << k << "_re,multiplier" << k << "_im";
  o << ",stability\n";
  for (const FamilyPoint& p : r.family.points) {
    o << format_number(p.parameter);
    for (Eigen::Index k = 0; k < p.values.size(); ++k) o << ',' << format_number(p.values[k]);
    o << ',' << format_number(p.period);
    for (const auto& z : p.multipliers)
      o << ',' << format_number(z.real()) << ',' << format_number(z.imag());
    o << ',' << p.stability << '\n';
  }
}

/// The JSON object of docs/continuation.md §5 (without `csv`).
io::Json family_json(const ContinueArgs& a, const Run& r, double p0, double p1) {
  io::Json points = io::Json::array(), events = io::Json::array();
  for (const FamilyPoint& p : r.family.points) points.push_back(point_json(p, r.names));
  for (const BifurcationEvent& e : r.family.events) {
    const io::Json pj = point_json(e.point, r.names);
    events.push_back({{"type", to_string(e.type)},
                      {"value", e.value},
                      {"solution", pj["values"]},
                      {"multipliers", pj["multipliers"]}});
  }
  io::Json j{{"scenario", a.scenario}, {"family", a.family},  {"parameter", a.parameter},
             {"range", {p0, p1}},      {"end", r.family.end}, {"points", points},
             {"events", events}};
  if (a.second) {
    io::Json bs = io::Json::array();
    for (const Boundary& b : r.boundaries) {
      io::Json pts = io::Json::array();
      for (const FamilyPoint& p : b.points) {
        pts.push_back({{"second", p.parameter},
                       {"parameter", p.values[2]},
                       {"theta0", p.values[0]},
                       {"dtheta0", p.values[1]},
                       {"stability", p.stability}});
      }
      bs.push_back({{"type", to_string(b.type)}, {"end", b.end}, {"points", pts}});
    }
    j["second"] = *a.second;
    j["boundaries"] = bs;
  }
  return j;
}

}  // namespace

int report(const ContinueArgs& a, const Run& r, double p0, double p1, io::AtomicFile* file) {
  if (file) {
    if (a.second) {
      write_boundaries_csv(file->stream(), r, a);
    } else {
      write_csv(file->stream(), r);
    }
    file->commit();
  }
  io::Json j = family_json(a, r, p0, p1);
  if (a.out) j["csv"] = *a.out;
  if (a.json) {
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop continue " << a.scenario << ": family " << a.family << " in " << a.parameter
            << " from " << format_number(p0) << " to " << format_number(p1) << "\n  "
            << r.family.points.size() << " points, ended: " << r.family.end << "\n";
  for (const BifurcationEvent& e : r.family.events) {
    std::cout << "  " << to_string(e.type) << " at " << a.parameter << " = "
              << format_number(e.value) << "\n";
  }
  for (const Boundary& b : r.boundaries) {
    std::cout << "  " << to_string(b.type) << " curve in " << *a.second << ": " << b.points.size()
              << " points (" << b.end << ")\n";
  }
  if (a.out) std::cout << (a.second ? "boundaries" : "family") << " written to " << *a.out << "\n";
  return kExitOk;
}

}  // namespace newtop::app
