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

/// The family's rows, after `prefix` (the branch column with --switch).
void write_rows(std::ostream& o, const Family& f, const std::string& prefix) {
  for (const FamilyPoint& p : f.points) {
    o << prefix << format_number(p.parameter);
    for (Eigen::Index k = 0; k < p.values.size(); ++k) o << ',' << format_number(p.values[k]);
    o << ',' << format_number(p.period);
    for (const auto& z : p.multipliers)
      o << ',' << format_number(z.real()) << ',' << format_number(z.imag());
    o << ',' << p.stability << '\n';
  }
}

void write_csv(std::ostream& o, const Run& r, bool branches) {
  if (branches) o << "branch,";
  o << "parameter";
  for (const auto& n : r.names) o << ',' << n;
  o << ",period";
  const std::size_t m = r.family.points.empty() ? 0 : r.family.points[0].multipliers.size();
  for (std::size_t k = 1; k <= m; ++k) o << ",multiplier" << k << "_re,multiplier" << k << "_im";
  o << ",stability\n";
  if (!branches) {
    write_rows(o, r.family, "");
    return;
  }
  write_rows(o, r.family, "0,");
  for (std::size_t i = 0; i < r.branches.size(); ++i)
    write_rows(o, r.branches[i].family, std::to_string(i + 1) + ",");
}

io::Json events_json(const Family& f, const std::vector<std::string>& names) {
  io::Json events = io::Json::array();
  for (const BifurcationEvent& e : f.events) {
    const io::Json pj = point_json(e.point, names);
    events.push_back({{"type", to_string(e.type)},
                      {"value", e.value},
                      {"solution", pj["values"]},
                      {"multipliers", pj["multipliers"]}});
  }
  return events;
}

/// The JSON object of docs/continuation.md §5 (without `csv`).
io::Json family_json(const ContinueArgs& a, const Run& r, double p0, double p1) {
  io::Json points = io::Json::array();
  for (const FamilyPoint& p : r.family.points) points.push_back(point_json(p, r.names));
  const io::Json events = events_json(r.family, r.names);
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
  if (a.switch_branches) {
    io::Json bs = io::Json::array();
    for (const Branch& b : r.branches) {
      io::Json pts = io::Json::array();
      for (const FamilyPoint& p : b.family.points) pts.push_back(point_json(p, r.names));
      bs.push_back({{"event", b.event},
                    {"type", to_string(r.family.events[b.event].type)},
                    {"end", b.family.end},
                    {"points", pts},
                    {"events", events_json(b.family, r.names)}});
    }
    j["branches"] = bs;
  }
  return j;
}

}  // namespace

int report(const ContinueArgs& a, const Run& r, double p0, double p1, io::AtomicFile* file) {
  if (file) {
    if (a.second) {
      write_boundaries_csv(file->stream(), r, a);
    } else {
      write_csv(file->stream(), r, a.switch_branches);
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
  for (std::size_t i = 0; i < r.branches.size(); ++i) {
    const Branch& b = r.branches[i];
    const BifurcationEvent& from = r.family.events[b.event];
    std::cout << "  branch " << i + 1 << " from the " << to_string(from.type) << " at "
              << a.parameter << " = " << format_number(from.value) << ": " << b.family.points.size()
              << " points, ended: " << b.family.end << "\n";
    for (const BifurcationEvent& e : b.family.events) {
      std::cout << "    " << to_string(e.type) << " at " << a.parameter << " = "
                << format_number(e.value) << "\n";
    }
  }
  if (a.out) std::cout << (a.second ? "boundaries" : "family") << " written to " << *a.out << "\n";
  return kExitOk;
}

}  // namespace newtop::app
