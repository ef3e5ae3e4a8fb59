#pragma once
/// \file
/// `newtop view`: a self-contained HTML page (three.js included) that plays a trajectory written
/// by `newtop simulate --out` (docs/cli.md, "view").

#include <optional>
#include <string>
#include <vector>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::viewer {

/// A trajectory CSV as newtop writes it: the columns by name, every cell a finite number.
struct Trajectory {
  std::string source;                        ///< file name, for the page and messages
  std::vector<std::string> names;            ///< header, in file order
  std::vector<std::vector<double>> columns;  ///< columns[i] holds the values of names[i]
  /// The column of that name, or null.
  const std::vector<double>* column(const std::string& name) const;
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  /// Whether this is an orbit run (docs/orbit.md §12: t[,nu], ω, γ and the orbit normal n).
  bool orbit() const { return column("normal1") != nullptr; }
  /// Whether the attitude columns q0, q1, q2, q3 (body → inertial, scalar first) are present; an
  /// orbit run's q0..q3 are its attitude relative to LVLH, not this.
  bool has_attitude() const { return column("q0") != nullptr && !orbit(); }
};

/// Parses and checks a trajectory CSV: the header starts `t,p,q,r,gamma1,gamma2,gamma3` (or, on an
/// orbit, `t[,nu],omega1,omega2,omega3,gamma1,gamma2,gamma3,normal1,normal2,normal3`), q0..q3
/// come all four or none, every row has the header's number of fields, every cell is a finite
/// number, t increases strictly, and γ and q are not zero (the page draws γ/|γ| and q/|q|; a
/// Runge–Kutta run lets |γ| drift, and the CSV's `geometric` column shows by how much). Throws
/// InputError `FILE:LINE: …` naming the column, what was expected and what was found.
Trajectory parse_trajectory(const std::string& text, const std::string& source);

/// Options of the page.
struct PageOptions {
  std::size_t max_frames = 5000;  ///< rows kept at most (evenly spaced, first and last kept)
};

/// The page: the template with three.js, the viewer's scripts and the data (the rows kept, the
/// integral columns, and with a scenario the body: inertia, gyrostat and shape — the mesh, the
/// ellipsoid or the point masses of its [mass_model], else the inertia ellipsoid).
std::string make_page(const Trajectory& trajectory, const io::Scenario* scenario,
                      const PageOptions& options);

/// The page of an orbit run with its scenario's body (the inertia ellipsoid; the angular
/// momentum m = Iω + k drawn).
std::string make_page(const Trajectory& trajectory, const io::OrbitScenario& scenario,
                      const PageOptions& options);

/// Indices of at most `limit` rows out of n, evenly spaced, the first and last always kept.
std::vector<std::size_t> frame_rows(std::size_t n, std::size_t limit);

}  // namespace newtop::viewer
